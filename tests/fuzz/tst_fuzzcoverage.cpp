// Every reader of outside bytes has a fuzz target here, with a seed corpus. The mission file types
// come from the code's own list (missionFileExtensions), so a file type added there without a fuzz
// target fails this test; the other readers (wire protocols, logs, terrain, profiles) are listed
// below, and a fuzz target no reader claims fails it too (a renamed target must be re-listed). And
// every target is built and runs each of its seeds through its entry point without a failure: the
// libFuzzer program itself (-runs=0) in the fuzz build, its seed runner (SeedRunner.cpp) elsewhere.
#include "MissionFiles.h"

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QTest>

#include <map>

using namespace sortie::mission::formats;

namespace {
const QDir kFuzzDir(QStringLiteral(SORTIE_FUZZ_DIR));

// Mission file formats, by formatName, and the target that fuzzes each one's reader.
const std::map<QString, QString> kMissionReaders{
    {QStringLiteral("Sortie mission"), QStringLiteral("fuzz_sortie_reader")},
    {QStringLiteral("QGroundControl plan"), QStringLiteral("fuzz_qgc_plan_reader")},
    {QStringLiteral("QGC WPL 110 waypoints"), QStringLiteral("fuzz_wpl_reader")},
    {QStringLiteral("KML"), QStringLiteral("fuzz_kml_reader")},
    {QStringLiteral("DJI WPML"), QStringLiteral("fuzz_wpml_reader")},
};

// Every other reader of bytes from outside: files, wire protocols, archives.
const std::map<QString, QString> kOtherReaders{
    {QStringLiteral("ZIP archives (KMZ)"), QStringLiteral("fuzz_zip_archive")},
    {QStringLiteral("HCI frames"), QStringLiteral("fuzz_hci_decoder")},
    {QStringLiteral("HCI routes (protobuf to route)"), QStringLiteral("fuzz_hci_route")},
    {QStringLiteral("HCI telemetry events (protobuf to telemetry)"), QStringLiteral("fuzz_hci_telemetry")},
    {QStringLiteral("VCI messages"), QStringLiteral("fuzz_vci")},
    {QStringLiteral("VCI fences (JSON)"), QStringLiteral("fuzz_vci_fence")},
    {QStringLiteral("VCI photo reports (JSON)"), QStringLiteral("fuzz_vci_photo")},
    {QStringLiteral("VCI telemetry, state and mission progress (JSON to telemetry)"), QStringLiteral("fuzz_vci_telemetry")},
    {QStringLiteral("SRTM .hgt tiles"), QStringLiteral("fuzz_hgt_tile")},
    {QStringLiteral("the server's elevation profiles (protobuf to heights along a path)"), QStringLiteral("fuzz_hci_elevation")},
    {QStringLiteral("energy profiles (JSON)"), QStringLiteral("fuzz_energy_profile")},
    {QStringLiteral("autosave files (crash recovery)"), QStringLiteral("fuzz_autosave")},
    {QStringLiteral("flight logs (.sortielog)"), QStringLiteral("fuzz_sortielog")},
    {QStringLiteral("telemetry blocks (.sortielog)"), QStringLiteral("fuzz_telemetry_block")},
    {QStringLiteral("the server's telemetry history (protobuf pages to a log)"), QStringLiteral("fuzz_server_history")},
    {QStringLiteral("airspace zones (GeoJSON)"), QStringLiteral("fuzz_geojson_zones")},
    {QStringLiteral("airspace zones (KML)"), QStringLiteral("fuzz_kml_zones")},
    {QStringLiteral("the zones the operator drew (GeoJSON with server ids)"), QStringLiteral("fuzz_custom_zones")},
    {QStringLiteral("UAS geographical zones (EUROCAE ED-269)"), QStringLiteral("fuzz_ed269_zones")},
    {QStringLiteral("UAS geographical zones (EUROCAE ED-318)"), QStringLiteral("fuzz_ed318_zones")},
    {QStringLiteral("server no-fly zones (protobuf to zone)"), QStringLiteral("fuzz_nfz_conversion")},
    {QStringLiteral("the server's route tools and their choices (protobuf to the algorithm catalog)"), QStringLiteral("fuzz_algorithm_catalog")},
    {QStringLiteral("ADS-B traffic (SBS-1 BaseStation lines)"), QStringLiteral("fuzz_sbs")},
    {QStringLiteral("ADS-B traffic from the server (protobuf to report)"), QStringLiteral("fuzz_adsb_report")},
    {QStringLiteral("tile server answers (body format, Retry-After)"), QStringLiteral("fuzz_tile_response")},
    {QStringLiteral("MBTiles metadata (offline map packs)"), QStringLiteral("fuzz_mbtiles_metadata")},
    {QStringLiteral("the operator's rasters through GDAL (DEMs, orthophotos)"), QStringLiteral("fuzz_raster")},
    {QStringLiteral("GPX tracks (geotagging)"), QStringLiteral("fuzz_gpx_track")},
    {QStringLiteral("photos' EXIF and XMP through exiv2 (geotagging)"), QStringLiteral("fuzz_photo_metadata")},
};
} // namespace

class TestFuzzCoverage : public QObject
{
    Q_OBJECT

    static void verifyTarget(const QString &reader, const QString &target)
    {
        QVERIFY2(kFuzzDir.exists(target + QStringLiteral(".cpp")), qPrintable(reader + QStringLiteral(": no ") + target + QStringLiteral(".cpp")));
        const QDir corpus(kFuzzDir.filePath(target.mid(5) + QStringLiteral("-corpus")));
        QVERIFY2(corpus.exists() && !corpus.entryList(QDir::Files).isEmpty(),
                 qPrintable(reader + QStringLiteral(": no seeds in ") + corpus.path()));
    }

private slots:
    void everyMissionFileTypeHasAFuzzTarget()
    {
        const QStringList extensions = missionFileExtensions();
        QVERIFY(extensions.size() >= 5);
        for (const QString &extension : extensions) {
            const auto format = formatForPath(QStringLiteral("file.") + extension);
            QVERIFY(format);
            const auto reader = kMissionReaders.find(formatName(*format));
            QVERIFY2(reader != kMissionReaders.end(), qPrintable(QStringLiteral(".%1 (%2) has no fuzz target").arg(extension, formatName(*format))));
            verifyTarget(reader->first, reader->second);
        }
    }

    void everyOtherReaderHasAFuzzTarget()
    {
        for (const auto &[reader, target] : kOtherReaders)
            verifyTarget(reader, target);
    }

    void everyTargetRunsAllItsSeeds_data()
    {
        QTest::addColumn<QString>("target");
        for (const QString &file : kFuzzDir.entryList({QStringLiteral("fuzz_*.cpp")}, QDir::Files))
            QTest::newRow(qPrintable(file)) << QFileInfo(file).completeBaseName();
    }
    void everyTargetRunsAllItsSeeds()
    {
        QFETCH(QString, target);
        const QString program = QDir(QStringLiteral(SORTIE_FUZZ_PROGRAMS_DIR)).filePath(QStringLiteral(SORTIE_FUZZ_PROGRAM_PREFIX) + target);
        QVERIFY2(QFileInfo(program).isExecutable(), qPrintable(program + QStringLiteral(" was not built")));
        const QString corpus = kFuzzDir.filePath(target.mid(5) + QStringLiteral("-corpus"));
        const int seeds = int(QDir(corpus).entryList(QDir::Files).size());
        QVERIFY2(seeds > 0, qPrintable(QStringLiteral("no seeds in ") + corpus));
        QProcess run;
        run.setProcessChannelMode(QProcess::MergedChannels);
        run.start(program, SORTIE_FUZZ_LIBFUZZER ? QStringList{QStringLiteral("-runs=0"), corpus} : QStringList{corpus});
        QVERIFY2(run.waitForFinished(600000), qPrintable(target + QStringLiteral(" did not finish its seeds")));
        const QString output = QString::fromLocal8Bit(run.readAll());
        QVERIFY2(run.exitStatus() == QProcess::NormalExit && run.exitCode() == 0,
                 qPrintable(QStringLiteral("%1 failed on its seeds (exit %2):\n%3").arg(target).arg(run.exitCode()).arg(output.right(4000))));
        // What ran: every seed (the seed runner counts them; libFuzzer reads them all with -runs=0).
        if (!SORTIE_FUZZ_LIBFUZZER)
            QVERIFY2(output.contains(QStringLiteral("seeds: ran %1 inputs").arg(seeds)), qPrintable(output));
        else
            QVERIFY2(output.contains(QStringLiteral("INITED")), qPrintable(output.right(4000)));
    }

    void everyFuzzTargetFuzzesAListedReader()
    {
        QStringList claimed;
        for (const auto *table : {&kMissionReaders, &kOtherReaders})
            for (const auto &entry : *table)
                claimed.append(entry.second + QStringLiteral(".cpp"));
        for (const QString &file : kFuzzDir.entryList({QStringLiteral("fuzz_*.cpp")}, QDir::Files))
            QVERIFY2(claimed.contains(file), qPrintable(file + QStringLiteral(" fuzzes no listed reader")));
    }
};

QTEST_GUILESS_MAIN(TestFuzzCoverage)
#include "tst_fuzzcoverage.moc"
