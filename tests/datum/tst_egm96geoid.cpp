// The EGM96 geoid through PROJ: against values read by hand from the grid itself, against a second,
// independent reading of the grid in this test, and a missing grid refused with its name.
#include "Egm96Geoid.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtEndian>
#include <QtTest>

#include <cmath>

using namespace sortie::datum;

namespace {

// The .gtx layout (NOAA VDatum): four big-endian doubles (south latitude, west longitude, latitude
// and longitude step), two big-endian int32 (rows, columns), then rows × columns big-endian floats
// from the south-west corner, row by row. Bilinear between the four surrounding nodes, as PROJ does.
class GtxGrid
{
public:
    explicit GtxGrid(const QString &path)
    {
        QFile f(path);
        if (f.open(QIODevice::ReadOnly))
            m_bytes = f.readAll();
    }
    bool ok() const { return m_bytes.size() > 40; }
    double at(double lat, double lon) const
    {
        const double lat0 = header(0), lon0 = header(1), dlat = header(2), dlon = header(3);
        const int cols = qFromBigEndian<qint32>(m_bytes.constData() + 36);
        const double x = std::fmod(lon - lon0 + 720.0, 360.0) / dlon, y = (lat - lat0) / dlat;
        const int c = int(x), r = int(y);
        const double fx = x - c, fy = y - r;
        const auto v = [&](int row, int col) {
            const quint32 bits = qFromBigEndian<quint32>(m_bytes.constData() + 40 + 4 * (qsizetype(row) * cols + col % cols));
            float value;
            std::memcpy(&value, &bits, 4);
            return double(value);
        };
        return v(r, c) * (1 - fx) * (1 - fy) + v(r, c + 1) * fx * (1 - fy) + v(r + 1, c) * (1 - fx) * fy + v(r + 1, c + 1) * fx * fy;
    }

private:
    double header(int i) const
    {
        const quint64 bits = qFromBigEndian<quint64>(m_bytes.constData() + 8 * i);
        double d;
        std::memcpy(&d, &bits, 8);
        return d;
    }
    QByteArray m_bytes;
};

} // namespace

class TestEgm96Geoid : public QObject
{
    Q_OBJECT

private slots:
    void undulationMatchesTheGridByHand_data()
    {
        QTest::addColumn<double>("lat");
        QTest::addColumn<double>("lon");
        QTest::addColumn<double>("expected");
        // Read from /usr/share/proj/egm96_15.gtx (proj-data 9.1.1) by a one-off Python script with
        // the same layout and bilinear interpolation, rounded to 1 mm. (0, 0): 17.16 m, the value
        // every EGM96 table gives for the Gulf of Guinea; Sri Lanka's low, about -105 m.
        QTest::newRow("Riga") << 56.9496 << 24.1052 << 20.591;
        QTest::newRow("the test route's quay") << 56.9765 << 24.0735 << 20.504;
        QTest::newRow("0,0") << 0.0 << 0.0 << 17.162;
        QTest::newRow("south of Sri Lanka") << 5.0 << 78.0 << -104.683;
        QTest::newRow("Sydney") << -33.8688 << 151.2093 << 22.420;
        QTest::newRow("Everest") << 27.9881 << 86.925 << -28.866;
    }

    void undulationMatchesTheGridByHand()
    {
        QFETCH(double, lat);
        QFETCH(double, lon);
        QFETCH(double, expected);
        QString error;
        const auto geoid = Egm96Geoid::open(Egm96Geoid::defaultGridPath(), &error);
        QVERIFY2(geoid, qPrintable(error));
        const auto n = geoid->undulation(lat, lon);
        QVERIFY(n);
        QVERIFY2(std::abs(*n - expected) < 0.002, qPrintable(QString::number(*n, 'f', 4)));
        // The same point read straight from the grid by this test's own reader.
        const GtxGrid grid(Egm96Geoid::defaultGridPath());
        QVERIFY(grid.ok());
        QVERIFY(std::abs(*n - grid.at(lat, lon)) < 0.001);
    }

    void convertsBothWays()
    {
        QString error;
        const auto geoid = Egm96Geoid::open(Egm96Geoid::defaultGridPath(), &error);
        QVERIFY(geoid);
        // 100 m above the ellipsoid in Riga is 100 - 20.59 m above the sea.
        const auto amsl = geoid->amslFromEllipsoidal(56.9496, 24.1052, 100.0);
        QVERIFY(amsl);
        QVERIFY(std::abs(*amsl - 79.409) < 0.002);
        const auto back = geoid->ellipsoidalFromAmsl(56.9496, 24.1052, *amsl);
        QVERIFY(back);
        QVERIFY(std::abs(*back - 100.0) < 1e-6);
        QVERIFY(!geoid->undulation(123.0, 0.0));  // not a latitude
        QVERIFY(!geoid->undulation(std::nan(""), 0.0));
    }

    void aMissingGridIsAnErrorNamingIt()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("egm96_15.gtx"));
        QString error;
        QVERIFY(!Egm96Geoid::open(path, &error));
        QVERIFY2(error.contains(path) && error.contains(QStringLiteral("proj-data")), qPrintable(error));
        // A file that is not a grid: PROJ's reason, with the file.
        QFile junk(path);
        QVERIFY(junk.open(QIODevice::WriteOnly));
        junk.write("not a grid");
        junk.close();
        error.clear();
        QVERIFY(!Egm96Geoid::open(path, &error));
        QVERIFY2(error.contains(path), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestEgm96Geoid)
#include "tst_egm96geoid.moc"
