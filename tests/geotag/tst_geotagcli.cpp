// sortie-log geotag as the operator runs it, a separate process (as tst_sortielog runs sortie-log):
// its exit status (0 every photo tagged, 2 some not, 1 bad usage or input), its JSON, its messages
// naming what is wrong, the copies it writes, and the originals it leaves alone.
#include "GeotagTestSupport.h"
#include "SortieLogRun.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using namespace sortie;
using sortie::test::describe;
using sortie::test::Run;
using sortie::test::sortieLog;

class TestGeotagCli : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_photos, m_gpx, m_log;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_photos = m_dir.filePath(QStringLiteral("card"));
        QVERIFY(QDir().mkpath(m_photos));
        // A straight minute north at 1 m/s-ish, one point a second, 100 m AMSL.
        std::vector<test::GpxPoint> points;
        test::LoggedVehicle a{QStringLiteral("VCI:a"), QStringLiteral("EMU-101"), {}}, b{QStringLiteral("VCI:b"), QStringLiteral("EMU-102"), {}};
        for (int s = 0; s <= 60; ++s) {
            points.push_back({int64_t(s) * 1000, 56.95 + 1e-5 * s, 24.1, 100});
            a.samples.push_back({s * 1000.0, 56.95 + 1e-5 * s, 24.1, 100, 20});
            b.samples.push_back({s * 1000.0, 56.96, 24.2 + 1e-5 * s, 110, 30});
        }
        m_gpx = m_dir.filePath(QStringLiteral("track.gpx"));
        test::writeGpx(m_gpx, points);
        m_log = m_dir.filePath(QStringLiteral("two.sortielog"));
        QCOMPARE(test::writeFlightLog(m_log, {a, b}), QString());
        for (int i = 0; i < 5; ++i) {
            const QString path = QDir(m_photos).filePath(QStringLiteral("DJI_%1.JPG").arg(i, 4, 10, QLatin1Char('0')));
            test::writeJpeg(path, i);
            test::setCameraTags(path, test::takenAt(10'000 + i * 7'500));
        }
    }

    void everyPhotoTaggedExitsZero()
    {
        const QString out = m_dir.filePath(QStringLiteral("out-gpx"));
        const Run r = sortieLog({QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--out"), out, QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(json.value(QStringLiteral("photos")).toInt(), 5);
        QCOMPARE(json.value(QStringLiteral("tagged")).toInt(), 5);
        QCOMPARE(json.value(QStringLiteral("offset")).toDouble(), 0.0);
        QCOMPARE(json.value(QStringLiteral("untagged")).toArray().size(), 0);
        const auto got = test::readGps(QDir(out).filePath(QStringLiteral("DJI_0001.JPG")));
        QVERIFY(got.latitude && std::fabs(*got.latitude - (56.95 + 1e-5 * 17.5)) < 1e-6);
        QVERIFY(got.altitude && std::fabs(*got.altitude - 100) < 0.1);
        QVERIFY(QFile::exists(QDir(out).filePath(QStringLiteral("geo.txt"))));
        QVERIFY(QFile::exists(QDir(out).filePath(QStringLiteral("geotags.csv"))));
    }

    void someUntaggedExitsTwoAndNamesThem()
    {
        // The camera 30 s late: the last photos fall after the track.
        const QString out = m_dir.filePath(QStringLiteral("out-late"));
        const Run r = sortieLog({QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--out"), out,
                                 QStringLiteral("--offset"), QStringLiteral("22.5"), QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 2, qPrintable(describe(r)));
        const QJsonObject json = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(json.value(QStringLiteral("photos")).toInt(), 5);
        QCOMPARE(json.value(QStringLiteral("tagged")).toInt(), 4); // at 32.5, 40, 47.5 and 55 s; the last at 62.5 s
        QCOMPARE(json.value(QStringLiteral("offset")).toDouble(), 22.5);
        const QJsonArray untagged = json.value(QStringLiteral("untagged")).toArray();
        QCOMPARE(untagged.size(), 1);
        const QJsonObject late = untagged.at(0).toObject();
        QCOMPARE(late.value(QStringLiteral("file")).toString(), QStringLiteral("DJI_0004.JPG"));
        QVERIFY2(late.value(QStringLiteral("reason")).toString().contains(QStringLiteral("2.5 s after the track ends")), qPrintable(describe(r)));
        QVERIFY(!QFile::exists(QDir(out).filePath(QStringLiteral("DJI_0004.JPG"))));
        const auto got = test::readGps(QDir(out).filePath(QStringLiteral("DJI_0000.JPG")));
        QVERIFY(got.latitude && std::fabs(*got.latitude - (56.95 + 1e-5 * 32.5)) < 1e-6);
        // Without --json: the untagged photo named with its reason.
        const Run text = sortieLog({QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--out"), out,
                                    QStringLiteral("--offset"), QStringLiteral("22.5")});
        QVERIFY2(text.exitCode == 2 && text.out.contains("DJI_0004.JPG: not tagged: taken at") && text.out.contains("4 of 5 photos tagged"),
                 qPrintable(describe(text)));
        // A negative offset (the camera ahead of the track): the first photo falls before it.
        const Run early = sortieLog({QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--out"),
                                     m_dir.filePath(QStringLiteral("out-early")), QStringLiteral("--offset"), QStringLiteral("-12.5"), QStringLiteral("--json")});
        QVERIFY2(early.exitCode == 2, qPrintable(describe(early)));
        const QJsonObject e = QJsonDocument::fromJson(early.out).object();
        QCOMPARE(e.value(QStringLiteral("offset")).toDouble(), -12.5);
        QCOMPARE(e.value(QStringLiteral("tagged")).toInt(), 4);
        const QJsonObject first = e.value(QStringLiteral("untagged")).toArray().at(0).toObject();
        QCOMPARE(first.value(QStringLiteral("file")).toString(), QStringLiteral("DJI_0000.JPG"));
        QVERIFY2(first.value(QStringLiteral("reason")).toString().contains(QStringLiteral("2.5 s before the track starts")), qPrintable(describe(early)));
    }

    void aFlightLogNeedsItsVehicleWhenItHoldsSeveral()
    {
        const QString out = m_dir.filePath(QStringLiteral("out-log"));
        Run r = sortieLog({QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--out"), out});
        QVERIFY2(r.exitCode == 1, qPrintable(describe(r)));
        QVERIFY2(r.err.contains("holds 2 vehicles (EMU-101, EMU-102): choose one with --vehicle"), qPrintable(describe(r)));
        r = sortieLog({QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--out"), out, QStringLiteral("--vehicle"), QStringLiteral("EMU-109")});
        QVERIFY2(r.exitCode == 1 && r.err.contains("no vehicle \"EMU-109\""), qPrintable(describe(r)));
        r = sortieLog({QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--out"), out,
                       QStringLiteral("--vehicle"), QStringLiteral("EMU-102"), QStringLiteral("--json")});
        QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
        QCOMPARE(QJsonDocument::fromJson(r.out).object().value(QStringLiteral("tagged")).toInt(), 5);
        const auto got = test::readGps(QDir(out).filePath(QStringLiteral("DJI_0002.JPG")));
        QVERIFY(got.longitude && std::fabs(*got.longitude - (24.2 + 1e-5 * 25)) < 1e-6);
        QVERIFY(got.altitude && std::fabs(*got.altitude - 110) < 0.1);
        QVERIFY(got.relativeAltitude && std::fabs(*got.relativeAltitude - 30) < 0.1);
        // Text output: a summary line.
        r = sortieLog({QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_log, QStringLiteral("--out"), out, QStringLiteral("--vehicle"), QStringLiteral("VCI:a")});
        QVERIFY2(r.exitCode == 0 && r.out.contains("5 of 5 photos tagged"), qPrintable(describe(r)));
    }

    void badUsageExitsOneSayingWhat()
    {
        const QString out = m_dir.filePath(QStringLiteral("out-bad"));
        const QString badGpx = m_dir.filePath(QStringLiteral("bad.gpx"));
        {
            QFile f(badGpx);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("<gpx version=\"1.1\">\n<trk><trkseg>\n<trkpt lat=\"north\" lon=\"24\"/>\n</trkseg></trk></gpx>\n");
        }
        const QString empty = m_dir.filePath(QStringLiteral("empty"));
        QVERIFY(QDir().mkpath(empty));
        const struct {
            QStringList args;
            const char *expect;
        } cases[] = {
            {{QStringLiteral("geotag"), m_photos, QStringLiteral("--out"), out}, "geotag needs --track"},
            {{QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_gpx}, "geotag needs --out"},
            {{QStringLiteral("geotag"), QStringLiteral("--track"), m_gpx, QStringLiteral("--out"), out}, "one photo folder"},
            {{QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--out"), out, QStringLiteral("--offset"), QStringLiteral("soon")}, "--offset takes seconds"},
            {{QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--out"), out, QStringLiteral("--speed"), QStringLiteral("2")}, "unknown option --speed"},
            {{QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_dir.filePath(QStringLiteral("none.gpx")), QStringLiteral("--out"), out}, "none.gpx: no such file"},
            {{QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), badGpx, QStringLiteral("--out"), out}, "bad.gpx:3: a track point needs lat"},
            {{QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--out"), out, QStringLiteral("--vehicle"), QStringLiteral("EMU-101")}, "is a GPX file"},
            {{QStringLiteral("geotag"), empty, QStringLiteral("--track"), m_gpx, QStringLiteral("--out"), out}, "holds no photos"},
            {{QStringLiteral("geotag"), m_photos, QStringLiteral("--track"), m_gpx, QStringLiteral("--out"), m_photos}, "the photos' own folder"},
        };
        for (const auto &c : cases) {
            const Run r = sortieLog(c.args);
            QVERIFY2(r.exitCode == 1, qPrintable(c.args.join(QLatin1Char(' ')) + QLatin1Char('\n') + describe(r)));
            QVERIFY2(r.err.contains(c.expect), qPrintable(QString::fromLatin1(c.expect) + QStringLiteral(" not said:\n") + describe(r)));
        }
        QVERIFY(!QDir(out).exists() || QDir(out).entryList(QDir::Files).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestGeotagCli)
#include "tst_geotagcli.moc"
