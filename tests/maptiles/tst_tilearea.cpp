// Which tiles cover an area: rectangles in closed form, polygons (convex, concave, across rows)
// against a brute force that clips the polygon to every tile of its bounding box, the antimeridian,
// margins, and bad areas refused with a reason.
#include "TileArea.h"
#include "TileId.h"
#include "TileUrlTemplate.h"

#include <QTest>

#include <cmath>

using namespace sortie::maptiles;

namespace {
constexpr double kPi = 3.14159265358979323846;
QPointF mercator(QPointF lonLat)
{
    const double lat = lonLat.y() * kPi / 180;
    return {(lonLat.x() + 180) / 360, 0.5 - std::log(std::tan(kPi / 4 + lat / 2)) / (2 * kPi)};
}

// Area of the polygon clipped to an axis-aligned box (Sutherland-Hodgman), in squared units.
double clippedArea(QList<QPointF> poly, double x0, double y0, double x1, double y1)
{
    const auto clip = [&](auto inside, auto cut) {
        QList<QPointF> out;
        for (qsizetype i = 0; i < poly.size(); ++i) {
            const QPointF a = poly[i], b = poly[(i + 1) % poly.size()];
            if (inside(b)) {
                if (!inside(a))
                    out.append(cut(a, b));
                out.append(b);
            } else if (inside(a)) {
                out.append(cut(a, b));
            }
        }
        poly = out;
    };
    const auto atX = [](double x) { return [x](QPointF a, QPointF b) { return QPointF(x, a.y() + (x - a.x()) * (b.y() - a.y()) / (b.x() - a.x())); }; };
    const auto atY = [](double y) { return [y](QPointF a, QPointF b) { return QPointF(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()), y); }; };
    clip([&](QPointF p) { return p.x() >= x0; }, atX(x0));
    clip([&](QPointF p) { return p.x() <= x1; }, atX(x1));
    clip([&](QPointF p) { return p.y() >= y0; }, atY(y0));
    clip([&](QPointF p) { return p.y() <= y1; }, atY(y1));
    double area = 0;
    for (qsizetype i = 0; i < poly.size(); ++i)
        area += poly[i].x() * poly[(i + 1) % poly.size()].y() - poly[(i + 1) % poly.size()].x() * poly[i].y();
    return std::abs(area) / 2;
}

QSet<quint64> bruteForce(const QList<QPointF> &lonLat, int zoom)
{
    QList<QPointF> poly;
    for (const QPointF &p : lonLat)
        poly.append(mercator(p) * (1 << zoom));
    double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
    for (const QPointF &p : poly)
        x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y()), x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
    QSet<quint64> tiles;
    for (int y = int(std::floor(y0)); y <= int(std::floor(y1)); ++y)
        for (int x = int(std::floor(x0)); x <= int(std::floor(x1)); ++x)
            if (clippedArea(poly, x, y, x + 1, y + 1) > 1e-9)
                tiles.insert(TileId{zoom, x, y}.packed());
    return tiles;
}

QSet<quint64> fromSpans(const TileArea &area, int zoom)
{
    QSet<quint64> tiles;
    for (const TileSpan &span : area.spans(zoom))
        for (int x = span.firstColumn; x <= span.lastColumn; ++x)
            tiles.insert(TileId{zoom, x, span.row}.packed());
    return tiles;
}
} // namespace

class TestTileArea : public QObject
{
    Q_OBJECT

private slots:
    // A template's keys never reach what is shown or logged: each named key's value, as written or
    // percent-encoded, and a password in the user part become "•••"; placeholders, other query
    // items and a key too short to be one stay.
    void secretsInATemplateAreRedacted()
    {
        const TileUrlTemplate t(QStringLiteral("https://maps:s3cr%2Ft-pass@{s}.tiles.example/{z}/{x}/{y}.png?style=dark&apikey=Ab12Cd34Ef"
                                               "&access_token=pk.eyJ1%3D%3D&key={k}&token=x&lang=lv"));
        QCOMPARE(t.secrets(), (QStringList{QStringLiteral("Ab12Cd34Ef"), QStringLiteral("pk.eyJ1%3D%3D"), QStringLiteral("x"),
                                           QStringLiteral("s3cr%2Ft-pass")}));
        const QString error = QStringLiteral("Error transferring https://a.tiles.example/3/4/2.png?style=dark&apikey=Ab12Cd34Ef"
                                             "&access_token=pk.eyJ1== - server replied: Forbidden (s3cr/t-pass)");
        const QString shown = t.redacted(error);
        QCOMPARE(shown, QStringLiteral("Error transferring https://a.tiles.example/3/4/2.png?style=dark&apikey=•••"
                                       "&access_token=••• - server replied: Forbidden (•••)"));
        for (const QString &secret : {QStringLiteral("Ab12Cd34Ef"), QStringLiteral("pk.eyJ1"), QStringLiteral("s3cr")})
            QVERIFY2(!shown.contains(secret), qPrintable(shown));
        // A template without secrets changes nothing.
        const TileUrlTemplate plain(QStringLiteral("https://tile.example.org/{z}/{x}/{y}.png?lang=lv"));
        QVERIFY(plain.secrets().isEmpty());
        QCOMPARE(plain.redacted(error), error);
    }

    void wholeWorldIsEveryTile()
    {
        const TileArea world = TileArea::rectangle({-85.0511, -180, 85.0511, 180});
        for (int z = 0; z <= 6; ++z)
            QCOMPARE(world.tileCount(z), qint64(1) << (2 * z));
        QCOMPARE(world.tileCount(0, 3), 1 + 4 + 16 + 64);
    }

    void rectangleCountsMatchItsTiles()
    {
        // Around Riga, zoom 10 to 16.
        const TileArea area = TileArea::rectangle({56.90, 23.95, 57.00, 24.20});
        qint64 total = 0;
        for (int z = 10; z <= 16; ++z) {
            const QSet<quint64> tiles = fromSpans(area, z);
            QCOMPARE(area.tileCount(z), qint64(tiles.size()));
            const QList<QPointF> corners{{23.95, 56.90}, {24.20, 56.90}, {24.20, 57.00}, {23.95, 57.00}};
            QCOMPARE(tiles, bruteForce(corners, z));
            total += tiles.size();
        }
        QCOMPARE(area.tileCount(10, 16), total);
    }

    void polygonsMatchBruteForce_data()
    {
        QTest::addColumn<QList<QPointF>>("corners");
        QTest::newRow("triangle") << QList<QPointF>{{24.0, 56.9}, {24.3, 56.95}, {24.1, 57.1}};
        QTest::newRow("concave U") << QList<QPointF>{{24.0, 56.9}, {24.4, 56.9}, {24.4, 57.2}, {24.3, 57.2}, {24.3, 57.0},
                                                     {24.1, 57.0}, {24.1, 57.2}, {24.0, 57.2}};
        QTest::newRow("thin diagonal") << QList<QPointF>{{10.0, 45.0}, {10.001, 45.0}, {10.5, 45.4}, {10.499, 45.4}};
        QList<QPointF> star; // a ten-pointed star south of the equator
        for (int i = 0; i < 20; ++i) {
            const double a = 2 * kPi * i / 20, r = i % 2 ? 0.1 : 0.3;
            star.append({150.2 + r * std::cos(a), -33.8 + r * std::sin(a)});
        }
        QTest::newRow("southern star") << star;
    }

    void polygonsMatchBruteForce()
    {
        QFETCH(QList<QPointF>, corners);
        const TileArea area = TileArea::polygon(corners);
        QVERIFY2(!area.isEmpty(), qPrintable(area.problem()));
        for (int z = 6; z <= 13; ++z) {
            const QSet<quint64> expected = bruteForce(corners, z);
            QCOMPARE(area.tileCount(z), qint64(expected.size()));
            QCOMPARE(fromSpans(area, z), expected);
        }
    }

    void tileEdgesAreNotCounted()
    {
        // Exactly the four tiles of zoom 1's north-west quarter, edges on tile edges: 4 at zoom 2.
        const TileArea area = TileArea::polygon({{-180, 85.0511287798066}, {0, 85.0511287798066}, {0, 0}, {-180, 0}});
        QCOMPARE(area.tileCount(1), 1);
        QCOMPARE(area.tileCount(2), 4);
    }

    void antimeridian()
    {
        // Fiji: 177° E to 178° W.
        const TileArea area = TileArea::rectangle({-19, 177, -16, -178});
        const QList<TileSpan> spans = area.spans(8);
        QVERIFY(!spans.isEmpty());
        const int row = spans.first().row;
        QList<TileSpan> first;
        for (const TileSpan &span : spans)
            if (span.row == row)
                first.append(span);
        QCOMPARE(first.size(), 2); // both ends of the row
        QCOMPARE(first.at(0).firstColumn, 0);
        QCOMPARE(first.at(1).lastColumn, 255);
        const TileArea west = TileArea::rectangle({-19, 177, -16, 180});
        const TileArea east = TileArea::rectangle({-19, -180, -16, -178});
        QCOMPARE(area.tileCount(8), west.tileCount(8) + east.tileCount(8));
        const TileArea crossing = TileArea::polygon({{179, -17}, {-179, -17}, {-179, -18}});
        QVERIFY(crossing.isEmpty());
        QVERIFY2(crossing.problem().contains(QStringLiteral("antimeridian")), qPrintable(crossing.problem()));
    }

    void margins()
    {
        const GeoBounds point{56.95, 24.1, 56.95, 24.1};
        QVERIFY(!point.isValid());
        const GeoBounds grown = point.grown(1000);
        QVERIFY(grown.isValid());
        // 1 km is 1/111.32 of a degree of latitude; longitude widened by 1/cos(latitude).
        QCOMPARE(qRound((grown.north - grown.south) * 1e4), qRound(2000 / 111319.49 * 1e4));
        QVERIFY(grown.east - grown.west > 2 * (grown.north - grown.south) * 0.99 / std::cos(57 * kPi / 180) * 0.5);
        const GeoBounds wide = GeoBounds{0, -179.9, 1, 179.9}.grown(50000);
        QCOMPARE(wide.west, -180.0);
        QCOMPARE(wide.east, 180.0);
        const GeoBounds dateLine = GeoBounds{0, 179.99, 1, 180}.grown(5000);
        QVERIFY(dateLine.east < 0 && dateLine.west > 0); // now across the antimeridian
    }

    void badAreasAreRefusedWithAReason()
    {
        QVERIFY(TileArea::polygon({{1, 2}, {3, 4}}).problem().contains(QStringLiteral("three corners")));
        const TileArea nan = TileArea::polygon({{1, 2}, {3, 4}, {qQNaN(), 5}});
        QVERIFY2(nan.problem().contains(QStringLiteral("Corner 3")), qPrintable(nan.problem()));
        QVERIFY(TileArea::rectangle({10, 5, 5, 6}).problem().contains(QStringLiteral("not a valid")));
        // A bow tie: its two halves would count, the crossing edges named instead.
        const TileArea bowTie = TileArea::polygon({{10, 45}, {11, 46}, {11, 45}, {10, 46}});
        QVERIFY(bowTie.isEmpty());
        QVERIFY2(bowTie.problem().contains(QStringLiteral("corner 1 and corner 3 cross")), qPrintable(bowTie.problem()));
        // Corners touching an edge, and a corner clicked twice, are not crossings.
        QVERIFY(!TileArea::polygon({{10, 45}, {11, 45}, {11, 45}, {11, 46}, {10.5, 45}}).isEmpty());
        QCOMPARE(TileArea().tileCount(0, 20), 0);
        QCOMPARE(TileArea::rectangle({0, 0, 1, 1}).tileCount(TileArea::kMaximumZoom + 1), 0);
    }
};

QTEST_GUILESS_MAIN(TestTileArea)
#include "tst_tilearea.moc"
