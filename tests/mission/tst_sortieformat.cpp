// The native .sortie format: exact round trip of everything in the model (HCI provenance
// included), migration from schema 1, refusal of newer schemas, and errors that name the line,
// column or JSON path.
#include "AlgorithmCatalog.h"
#include "Camera.h"
#include "Domain.pb.h"
#include "HciOrigin.h"
#include "MissionFiles.h"
#include "MissionSamples.h"
#include "SortieFormat.h"

#include <QTemporaryDir>
#include <QTimeZone>
#include <QtTest>

using namespace sortie::mission;
using namespace sortie::mission::formats;
using namespace sortie::mission::test;
namespace pb = com::ugcs::ucs::proto;

namespace {
Mission fullMission()
{
    Mission m;
    m.name = QStringLiteral("Port survey — north pier");
    m.description = QStringLiteral("Quay inspection\nline two, \"quoted\"");
    Route r = mavlinkRoute();
    r.settings.profile = {QStringLiteral("EMU Copter"), 12, 4, 3, 25, {{7, builtInCameras().back()}}};
    r.settings.failsafes = {{FailsafeReason::GpsLost, FailsafeAction::Wait}, {FailsafeReason::LowBattery, FailsafeAction::Land}};
    r.settings.cornerRadius = 2;
    r.settings.takeoffHeight = 1.5;
    r.settings.plannedStart = QDateTime(QDate(2026, 6, 6), QTime(18, 30, 15, 250), QTimeZone::utc());
    r.settings.authorisations = {{QStringLiteral("LVA200"), QStringLiteral("LGS-2026-117")}, {QStringLiteral("CHE-77"), QStringLiteral("FOCA 12/b")}};
    r.settings.endAction = EndAction::ReturnHome;
    auto &b = std::get<Waypoint>(r.segments[2]);
    b.turnType = TurnType::BankTurn;
    b.actions.push_back(PanoramaAction{270, 30, 2, RotationDirection::CounterClockwise, 15, PanoramaMode::Video});
    b.actions.push_back(WaitAction{0, true});
    b.actions.push_back(HeadingAction{10, true});
    b.actions.push_back(CameraTriggerAction{TriggerState::ToggleRecording});
    CameraControlAction gimbal;  // roll and zoom not set: they stay unset
    gimbal.tiltDeg = 90;
    gimbal.yawDeg = -12.5;
    b.actions.push_back(gimbal);
    pb::ActionDefinition def;
    def.mutable_setservodefinition()->set_servoid(7);
    def.mutable_setservodefinition()->set_pwm(1500);
    b.actions.push_back(ServerAction{QByteArray::fromStdString(def.SerializeAsString())});
    pb::SegmentDefinition origin;
    origin.set_uuid("d1e2f3a4-b5c6-4d7e-8f90-a1b2c3d4e5f6");
    origin.mutable_unknown_fields()->AddVarint(999, 42);
    b.origin = hciOrigin(origin);
    AreaScan gsd = squareScan({56.96, 24.11}, 300);
    gsd.parameters.heightMode = ScanHeightMode::GroundSampleDistance;
    gsd.parameters.groundSampleDistanceCm = 1.7;
    gsd.parameters.toleranceMeters = 7.5;  // kept when set; the other scan leaves it to the server
    gsd.parameters.camera = {QStringLiteral("Tiny"), 6.17, 4.55, 4.5, 4000, 3000};
    syncDerivedFields(gsd.parameters);
    r.segments.insert(r.segments.begin() + 3, gsd);
    r.segments.push_back(squareScan({56.97, 24.12}, 200, 70));
    AreaScan spaced = squareScan({56.98, 24.12}, 150, 65);  // UgCS's area scan: passes a plain 25 m apart
    spaced.parameters.sideDistanceMeters = 25;
    r.segments.push_back(spaced);
    // Every other tool, and one Sortie does not know, kept with its server's bytes.
    for (const AlgorithmDefinition &def : AlgorithmCatalog::builtIn().algorithms()) {
        if (def.kind == AlgorithmKind::Waypoint || def.kind == AlgorithmKind::TakeOff || def.kind == AlgorithmKind::Landing
            || def.kind == AlgorithmKind::AreaScan)
            continue;
        AlgorithmSegment a;
        a.algorithm = def.className;
        a.figure = def.figure;
        const GeoPoint square[] = {{56.95, 24.1}, {56.95, 24.101}, {56.951, 24.101}, {56.951, 24.1}};
        for (int i = 0; i < std::max(def.minimumPoints, def.figure == FigureType::Polygon ? 4 : 1); ++i)
            a.points.push_back({square[i], def.figure == FigureType::Circle ? 35.0 : 0.0, AltitudeType::Agl});
        if (def.figure == FigureType::Circle)
            a.figureParameters = {42.5};
        for (const ParameterDefinition &p : def.parameters)
            if (!p.defaultValue.isEmpty() || p.name == QLatin1String("camera"))
                a.parameters.push_back({p.name, p.name == QLatin1String("camera") ? builtInCameras().front().name : p.defaultValue});
        r.segments.push_back(a);
    }
    AlgorithmSegment unknown;
    unknown.algorithm = QStringLiteral("com.example.SpiralAlgorithm");
    unknown.figure = FigureType::EightCurve;
    unknown.points = {{{56.9, 24.1}, 120, AltitudeType::Amsl}};
    unknown.parameters = {{QStringLiteral("turns"), QStringLiteral("7")}, {QStringLiteral("turns"), QStringLiteral("8")},
                          {QStringLiteral("note"), QStringLiteral("")}};
    unknown.actions.push_back(WaitAction{3, false});
    pb::SegmentDefinition unknownOrigin;
    unknownOrigin.set_uuid("spiral");
    unknownOrigin.mutable_unknown_fields()->AddVarint(4242, 7);
    unknown.origin = hciOrigin(unknownOrigin);
    r.segments.push_back(unknown);
    m.routes = {r, mavlinkRoute()};
    return m;
}

bool sameOrigins(const Mission &a, const Mission &b)
{
    const auto &wa = std::get<Waypoint>(a.routes[0].segments[2]);
    const auto &wb = std::get<Waypoint>(b.routes[0].segments[2]);
    if (!hciSegment(wa.origin) || !hciSegment(wb.origin))
        return false;
    const auto &oa = std::get<ServerAction>(wa.actions.back());
    const auto &ob = std::get<ServerAction>(wb.actions.back());
    return hciSegment(wa.origin)->SerializeAsString() == hciSegment(wb.origin)->SerializeAsString()
        && !oa.definition.isEmpty() && oa.definition == ob.definition;
}

bool sameIgnoringServerActionPointers(Mission a, Mission b)
{
    // Server actions compare by bytes here, above; after a file round trip the objects are new.
    for (Mission *m : {&a, &b})
        for (Route &r : m->routes)
            for (Segment &s : r.segments)
                if (Waypoint *w = asWaypoint(s))
                    for (auto &act : w->actions)
                        if (auto *o = std::get_if<ServerAction>(&act))
                            o->definition.clear();
    // The unknown algorithm's server bytes come back as they went.
    const auto &ua = std::get<AlgorithmSegment>(a.routes[0].segments.back());
    const auto &ub = std::get<AlgorithmSegment>(b.routes[0].segments.back());
    if (!hciSegment(ua.origin) || !hciSegment(ub.origin) || hciSegment(ua.origin)->SerializeAsString() != hciSegment(ub.origin)->SerializeAsString())
        return false;
    return a == b;
}
}

class TestSortieFormat : public QObject
{
    Q_OBJECT
private slots:
    void roundTripIsExact()
    {
        const Mission m = fullMission();
        const QByteArray bytes = writeSortie(m);
        const Result<Mission> back = readSortie(bytes);
        QVERIFY2(back.ok(), back.ok() ? "" : qPrintable(back.error().toString()));
        QVERIFY(sameIgnoringServerActionPointers(*back, m));
        QVERIFY(sameOrigins(*back, m));
        QCOMPARE(writeSortie(*back), bytes);  // and the bytes are stable
    }

    void migratesSchemaOne()
    {
        const QByteArray v1 = R"({"format": "sortie-mission", "schemaVersion": 1,
            "mission": {"name": "old", "routes": [{"name": "r", "speed": 6.5, "safeAltitude": 30,
              "waypoints": [{"lat": 56.9, "lon": 24.1, "alt": 40}, {"lat": 56.91, "lon": 24.11, "alt": 50, "altitudeType": "AMSL"}]}]}})";
        const Result<Mission> m = readSortie(v1);
        QVERIFY2(m.ok(), m.ok() ? "" : qPrintable(m.error().toString()));
        const Route &r = m->routes.at(0);
        QCOMPARE(r.settings.initialSpeed, 6.5);
        QCOMPARE(r.settings.safeAltitude, 30.0);
        QCOMPARE(int(r.segments.size()), 2);
        const auto &w = std::get<Waypoint>(r.segments[1]);
        QCOMPARE(w.altitudeType, AltitudeType::Amsl);
        QCOMPARE(w.speed, 6.5);
        QCOMPARE(w.position.longitude, 24.11);
        const QByteArray broken = R"({"format": "sortie-mission", "schemaVersion": 1, "mission": {"routes": [{"waypoints": [{"lat": 1}]}]}})";
        QCOMPARE(readSortie(broken).error().jsonPath, QStringLiteral("/mission/routes/0/waypoints/0"));
    }

    // Schema 2 named an area scan's parameters Sortie's way; schema 3 takes the UgCS wire names.
    void migratesSchemaTwo()
    {
        const QByteArray v2 = R"({"format": "sortie-mission", "schemaVersion": 2, "mission": {"name": "old", "routes": [{"name": "r",
            "segments": [{"type": "areaScan", "polygon": [[56.9, 24.1], [56.9, 24.11], [56.905, 24.11]],
              "camera": {"name": "Cam", "sensorWidthMm": 13.2, "sensorHeightMm": 8.8, "focalLengthMm": 8.8, "imageWidthPx": 5472, "imageHeightPx": 3648},
              "heightMode": "groundSampleDistance", "altitude": 60, "groundSampleDistanceCm": 1.5, "altitudeType": "AMSL",
              "frontOverlapPercent": 70, "sideOverlapPercent": 55, "directionDeg": 33, "turnaroundMeters": 12, "speed": 7}]}]}})";
        const Result<Mission> m = readSortie(v2);
        QVERIFY2(m.ok(), m.ok() ? "" : qPrintable(m.error().toString()));
        const AreaScanParameters &p = std::get<AreaScan>(m->routes.at(0).segments.at(0)).parameters;
        QCOMPARE(p.heightMode, ScanHeightMode::GroundSampleDistance);
        QCOMPARE(p.groundSampleDistanceCm, 1.5);
        QCOMPARE(p.altitudeType, AltitudeType::Amsl);
        QCOMPARE(p.frontOverlapPercent, 70.0);
        QCOMPARE(p.sideOverlapPercent, 55.0);
        QCOMPARE(p.sideDistanceMeters, 0.0);
        QCOMPARE(p.directionDeg, 33.0);
        QCOMPARE(p.turnaroundMeters, 12.0);
        QCOMPARE(p.speed, 7.0);
        QVERIFY(writeSortie(*m).contains("\"overlapSide\":55"));
        // A bad value in the new names is refused by the one parameter reader, naming its place.
        QByteArray bad = writeSortie(*m);
        bad.replace("\"overlapSide\":55", "\"overlapSide\":100");
        const Result<Mission> refused = readSortie(bad);
        QVERIFY(!refused.ok());
        QCOMPARE(refused.error().jsonPath, QStringLiteral("/mission/routes/0/segments/0/parameters/overlapSide"));
    }

    void oldSchemasWithWrongTypesAreErrorsNotCrashes()
    {
        // Found by fuzz_sortie_reader: a schema-2 segment whose "type" is a number threw out of the
        // migration; a schema-1 altitudeType that is no string did the same.
        const QByteArray v2 = R"({"format": "sortie-mission", "schemaVersion": 2, "mission": {"name": "m", "routes": [{"name": "r",
            "segments": [{"type": 61386, "latitude": 56.9, "longitude": 24.1, "altitude": 20}]}]}})";
        const Result<Mission> m2 = readSortie(v2);
        QVERIFY(!m2.ok());
        QVERIFY(m2.error().jsonPath.startsWith(QStringLiteral("/mission/routes/0/segments/0")));
        const QByteArray v1 = R"({"format": "sortie-mission", "schemaVersion": 1, "mission": {"name": "m", "routes": [{"name": "r",
            "waypoints": [{"lat": 56.9, "lon": 24.1, "alt": 20, "altitudeType": 7}]}]}})";
        const Result<Mission> m1 = readSortie(v1);
        QVERIFY(!m1.ok());
        QVERIFY(m1.error().jsonPath.startsWith(QStringLiteral("/mission/routes/0/segments/0")));
    }

    void refusesNewerSchema()
    {
        const Result<Mission> m = readSortie(R"({"format": "sortie-mission", "schemaVersion": 4, "mission": {"routes": []}})");
        QVERIFY(!m.ok());
        QCOMPARE(m.error().jsonPath, QStringLiteral("/schemaVersion"));
        QVERIFY(m.error().message.contains(QStringLiteral("newer")));
    }

    void syntaxErrorNamesLineAndColumn()
    {
        const QByteArray text = "{\n \"format\": \"sortie-mission\",\n \"schemaVersion\": 2\n \"mission\": {}\n}\n";
        const Result<Mission> m = readSortie(text);
        QVERIFY(!m.ok());
        QCOMPARE(m.error().line, 4);
        QVERIFY(m.error().column > 0);
    }

    void numberOverflowIsAnErrorWithItsLine()
    {
        // Found by fuzz_sortie_reader: nlohmann-json reports this one as out_of_range, not parse_error.
        const Result<Mission> m = readSortie("{\n \"format\": \"sortie-mission\",\n \"schemaVersion\": 1e999\n}");
        QVERIFY(!m.ok());
        QCOMPARE(m.error().line, 3);
        QCOMPARE(m.error().column, 19);
        QVERIFY(m.error().message.contains(QStringLiteral("overflow")));
    }

    // A planned start that is not a UTC date and time is named at its path; a missing one is now.
    void aPlannedStartMustBeUtc_data()
    {
        QTest::addColumn<QByteArray>("value");
        QTest::newRow("no time") << QByteArray("\"2026-06-06\"");
        QTest::newRow("local time") << QByteArray("\"2026-06-06T18:30:00\"");
        QTest::newRow("not a date") << QByteArray("\"saturday\"");
        QTest::newRow("a number") << QByteArray("1780770600");
    }
    void aPlannedStartMustBeUtc()
    {
        QFETCH(QByteArray, value);
        Mission m;
        m.routes.push_back(mavlinkRoute());
        QVERIFY(!readSortie(writeSortie(m))->routes[0].settings.plannedStart);
        m.routes[0].settings.plannedStart = QDateTime(QDate(2026, 6, 6), QTime(18, 30), QTimeZone::utc());
        QByteArray text = writeSortie(m);
        const QByteArray written = "\"plannedStart\": \"2026-06-06T18:30:00.000Z\"";
        QVERIFY2(text.contains(written), text.constData());
        text.replace(written, "\"plannedStart\": " + value);
        const Result<Mission> r = readSortie(text);
        QVERIFY(!r.ok());
        QCOMPARE(r.error().jsonPath, QStringLiteral("/mission/routes/0/plannedStart"));
    }

    void semanticErrorsNameTheJsonPath_data()
    {
        QTest::addColumn<QByteArray>("key");
        QTest::addColumn<QByteArray>("value");
        QTest::addColumn<QString>("path");
        QTest::newRow("latitude out of range") << QByteArray("latitude") << QByteArray("95") << QStringLiteral("/mission/routes/0/segments/1/latitude");
        QTest::newRow("altitude not a number") << QByteArray("altitude") << QByteArray("\"high\"") << QStringLiteral("/mission/routes/0/segments/1/altitude");
        QTest::newRow("unknown altitude type") << QByteArray("altitudeType") << QByteArray("\"ASL\"") << QStringLiteral("/mission/routes/0/segments/1/altitudeType");
        QTest::newRow("unknown turn type") << QByteArray("turnType") << QByteArray("\"Loop\"") << QStringLiteral("/mission/routes/0/segments/1/turnType");
    }
    void semanticErrorsNameTheJsonPath()
    {
        QFETCH(QByteArray, key);
        QFETCH(QByteArray, value);
        QFETCH(QString, path);
        Mission m;
        m.routes.push_back(mavlinkRoute());
        QByteArray text = writeSortie(m);
        QVERIFY(readSortie(text).ok());
        // Replace the value in the second segment (one segment per line).
        const qsizetype seg = text.indexOf("{\"type\":\"waypoint\"", text.indexOf("{\"type\":\"waypoint\"") + 1);
        const qsizetype at = text.indexOf("\"" + key + "\":", seg) + key.size() + 3;
        qsizetype end = at;
        while (text[end] != ',' && text[end] != '}')
            ++end;
        text.replace(at, end - at, value);
        const Result<Mission> r = readSortie(text);
        QVERIFY(!r.ok());
        QCOMPARE(r.error().jsonPath, path);
    }

    void oneSegmentPerLine()
    {
        Mission m;
        m.routes.push_back(mavlinkRoute());
        const QList<QByteArray> lines = writeSortie(m).split('\n');
        int segmentLines = 0;
        for (const QByteArray &l : lines)
            segmentLines += l.trimmed().startsWith("{\"type\":\"waypoint\"");
        QCOMPARE(segmentLines, int(m.routes[0].segments.size()));
    }

    void notASortieFile()
    {
        QVERIFY(readSortie(R"({"fileType": "Plan"})").error().message.contains(QStringLiteral("not a Sortie mission")));
        QVERIFY(!readSortie("").ok());
        QVERIFY(!readSortie("[1, 2]").ok());
    }

    void filesAreAtomicAndGated()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("m.sortie"));
        Mission m = fullMission();
        const Result<QStringList> saved = saveMission(m, path);
        QVERIFY2(saved.ok(), saved.ok() ? "" : qPrintable(saved.error().toString()));
        const Result<LoadedMission> loaded = loadMission(path);
        QVERIFY(loaded.ok());
        QVERIFY(sameIgnoringServerActionPointers(loaded->mission, m));

        // A route with a validation error is refused, and the file on disk stays as it was.
        std::get<Waypoint>(m.routes[1].segments[1]).altitude = 500;
        const Result<QStringList> refused = saveMission(m, path);
        QVERIFY(!refused.ok());
        QCOMPARE(refused.error().file, path);
        QVERIFY(refused.error().message.contains(QStringLiteral("Waypoint 2")));
        QVERIFY(sameIgnoringServerActionPointers(loadMission(path)->mission, fullMission()));
        QVERIFY(saveMission(m, path, {0, ValidationOverride::AcceptErrors}).ok());

        // Errors name the file.
        QFile bad(dir.filePath(QStringLiteral("bad.sortie")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{\"format\": \"sortie-mission\",\n\"schemaVersion\": 2,\n\"mission\": {\"routes\": [}\n}");
        bad.close();
        const Result<LoadedMission> failed = loadMission(bad.fileName());
        QVERIFY(!failed.ok());
        QVERIFY(failed.error().toString().startsWith(bad.fileName() + QStringLiteral(":3:")));
        QVERIFY(!loadMission(dir.filePath(QStringLiteral("missing.sortie"))).ok());
        QVERIFY(!loadMission(dir.filePath(QStringLiteral("x.docx"))).ok());
    }
};

QTEST_GUILESS_MAIN(TestSortieFormat)
#include "tst_sortieformat.moc"
