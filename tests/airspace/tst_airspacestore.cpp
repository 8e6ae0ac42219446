// The client's zone store (Airspace) over a real route model and analyzer: zones from every source
// in one set, the rule's errors in the route's validation and the upload gate, the operator's
// switches and buffer, files remembered, drawn zones kept across restarts; and ZoneEditor's
// commands: one undo step per edit and per gesture, refusals that change nothing.
#include "Airspace.h"
#include "AirspaceRule.h"
#include "CustomZoneFile.h"
#include "Geodesy.h"
#include "RouteAnalyzer.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "ValidationGate.h"
#include "ZoneEditor.h"
#include "ZoneListModel.h"

#include <QLocale>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTimeZone>
#include <QUndoStack>
#include <QtTest>

using namespace sortie::airspace;
using namespace sortie::mission;

namespace {
const GeoPoint kOrigin{56.95, 24.1};

// Four 1000 m legs east at 40 m AMSL.
Route lineRoute()
{
    Route r;
    for (int i = 0; i <= 4; ++i) {
        Waypoint w;
        w.position = geodesicDirect(kOrigin, 90, 1000.0 * i).point;
        w.altitude = 40;
        w.altitudeType = AltitudeType::Amsl;
        r.segments.push_back(w);
    }
    return r;
}

QGeoCoordinate at(double east, double north)
{
    const GeoPoint p = geodesicDirect(geodesicDirect(kOrigin, 90, east).point, 0, north).point;
    return {p.latitude, p.longitude};
}

// A 200 m square over leg 2 (1,400–1,600 m along the line).
QList<QGeoCoordinate> squareOverLeg2()
{
    return {at(1400, -100), at(1600, -100), at(1600, 100), at(1400, 100)};
}

int countRule(const ValidationReport &report, const QString &rule)
{
    int n = 0;
    for (const ValidationIssue &i : report.issues)
        n += i.rule == rule;
    return n;
}

QString firstMessage(const ValidationReport &report, const QString &rule)
{
    for (const ValidationIssue &i : report.issues)
        if (i.rule == rule)
            return i.message;
    return {};
}
} // namespace

class TstAirspaceStore : public QObject
{
    Q_OBJECT

    struct Fixture
    {
        explicit Fixture(const QString &dir, QString customFile = {})
            : settings(dir + QStringLiteral("/settings.ini"), QSettings::IniFormat)
        {
            model.resetRoute(lineRoute());
            store = std::make_unique<Airspace>(&settings, &analyzer, &model, nullptr, std::move(customFile));
        }
        QSettings settings;
        RouteModel model;
        RouteAnalyzer analyzer{&model};
        std::unique_ptr<Airspace> store;
    };

    QTemporaryDir m_dir;
    QString path(const char *name) const { return m_dir.filePath(QString::fromLatin1(name)); }
    void write(const char *name, const QByteArray &data)
    {
        QFile f(path(name));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(data);
    }

private slots:
    void init()
    {
        QVERIFY(m_dir.isValid());
        for (const QString &f : QDir(m_dir.path()).entryList(QDir::Files))
            QFile::remove(m_dir.filePath(f));
    }

    void aDrawnZoneIsAnErrorTheGateRefuses()
    {
        Fixture f(m_dir.path());
        f.analyzer.recomputeNow();
        QCOMPARE(f.analyzer.validation().errorCount(), 0);
        QVERIFY(f.store->crossings().empty());

        QSignalSpy changed(f.store.get(), &Airspace::changed);
        QCOMPARE(f.store->editor()->addPolygon(squareOverLeg2()), 0);
        QCOMPARE(changed.count(), 1);  // one set per change
        QCOMPARE(f.store->count(), 1);
        QCOMPARE(f.store->zoneSet()->zones().size(), size_t(1));
        QCOMPARE(f.store->selectedZone(), 0);  // a new zone is the chosen one
        f.analyzer.recomputeNow();
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-exclusion")), 1);
        const QString message = firstMessage(f.analyzer.validation(), QStringLiteral("airspace-exclusion"));
        QVERIFY2(message.startsWith(QStringLiteral("Leg 2 enters 'Zone 1' from 1,400 m to 1,600 m")), qPrintable(message));
        const sortie::mission::Result<void> refused = permitRelease(f.analyzer.validation(), ValidationOverride::None, QStringLiteral("Upload"));
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QStringLiteral("Zone 1")), qPrintable(refused.error().message));

        // Where it crosses, for the terrain profile: the distances and the zone's limits.
        QCOMPARE(f.store->crossingCount(), 1);
        const ZoneCrossing &crossing = f.store->crossings().front();
        QVERIFY(std::abs(crossing.from - 1400) < 0.5);
        QVERIFY(std::abs(crossing.to - 1600) < 0.5);
        QCOMPARE(crossing.leg, 2);
        QCOMPARE(crossing.zone, 0);
        QCOMPARE(crossing.name, QStringLiteral("Zone 1"));
        QCOMPARE(crossing.kind, ZoneKind::Exclusion);
        QVERIFY(!crossing.floor && !crossing.ceiling);  // the ground up, unlimited
        QVERIFY(crossing.path.size() >= 2);             // the stretch the map draws

        // The issue chooses its zone.
        f.store->setSelectedZone(-1);
        QVERIFY(f.store->selectZoneOfIssue(message));
        QCOMPARE(f.store->selectedZone(), 0);
        QVERIFY(!f.store->selectZoneOfIssue(QStringLiteral("Leg 9 enters 'Elsewhere'.")));

        // Above its ceiling the leg is clear; within the buffer it is a warning.
        QVERIFY(f.store->editor()->setLimits(0, QString(), QStringLiteral("30"), QStringLiteral("AMSL")));
        f.analyzer.recomputeNow();
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-exclusion")), 0);
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-near")), 1);
        QVERIFY(f.store->crossings().empty());
        f.store->setBuffer(5);
        f.analyzer.recomputeNow();
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-near")), 0);

        // A ceiling typed in German ("30,5") is read as the language writes it; text is refused.
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        const bool german = f.store->editor()->setLimits(0, QString(), QStringLiteral("30,5"), QStringLiteral("AMSL"));
        const bool words = f.store->editor()->setLimits(0, QString(), QStringLiteral("dreißig"), QStringLiteral("AMSL"));
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        QVERIFY(german);
        QVERIFY(!words);
        QCOMPARE(f.store->zoneAt(0).ceiling->metres, 30.5);

        // Switched off: kept, drawn, not checked.
        QVERIFY(f.store->editor()->setLimits(0, QString(), QString(), QStringLiteral("AMSL")));
        f.store->setActive(0, false);
        f.analyzer.recomputeNow();
        QCOMPARE(f.analyzer.validation().errorCount(), 0);
        QCOMPARE(f.store->count(), 1);
        QVERIFY(!f.store->zoneAt(0).active);
        QVERIFY(f.store->zones()->setData(f.store->zones()->index(0), true, ZoneListModel::ActiveRole));
        f.analyzer.recomputeNow();
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-exclusion")), 1);
    }

    void theBufferIsASetting()
    {
        {
            Fixture f(m_dir.path());
            QCOMPARE(f.store->buffer(), 20.0);
            QCOMPARE(f.store->rule()->buffer(), 20.0);
            f.store->setBuffer(75);
            f.store->setBuffer(-3);  // refused
            QCOMPARE(f.store->buffer(), 75.0);
        }
        Fixture again(m_dir.path());
        QCOMPARE(again.store->buffer(), 75.0);
        QCOMPARE(again.store->rule()->buffer(), 75.0);
    }

    void zoneFilesNameTheirBadFeaturesAndAreRemembered()
    {
        write("zones.geojson", R"({"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {"name": "RIX CTR", "radius": 150, "ceiling": 150, "reference": "AMSL"},
             "geometry": {"type": "Point", "coordinates": [24.1236, 56.95]}},
            {"type": "Feature", "properties": {"name": "Bad", "kind": "forbidden"},
             "geometry": {"type": "Point", "coordinates": [24.2, 56.95]}}]})");
        write("broken.geojson", "{\"type\": \n[");
        {
            Fixture f(m_dir.path());
            QVERIFY(f.store->loadFile(path("zones.geojson")));
            QCOMPARE(f.store->count(), 1);
            QCOMPARE(f.store->zoneAt(0).name, QStringLiteral("RIX CTR"));
            QCOMPARE(f.store->groupOf(0), Airspace::Group::File);
            QCOMPARE(f.store->problems().size(), 1);
            QVERIFY2(f.store->problems().front().contains(QStringLiteral("zones.geojson")) && f.store->problems().front().contains(QStringLiteral("'Bad'")),
                     qPrintable(f.store->problems().front()));
            const QModelIndex row = f.store->zones()->index(0);
            QCOMPARE(row.data(ZoneListModel::SourceRole).toString(), QStringLiteral("file"));
            QCOMPARE(row.data(ZoneListModel::FloorRole).toString(), QStringLiteral("ground"));
            QCOMPARE(row.data(ZoneListModel::CeilingRole).toString(), QStringLiteral("150 m AMSL"));
            QCOMPARE(row.data(ZoneListModel::KindRole).toString(), QStringLiteral("exclusion"));
            f.analyzer.recomputeNow();
            QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-exclusion")), 1);

            // A file that is not JSON: an error with its line, and nothing lost.
            QVERIFY(!f.store->loadFile(path("broken.geojson")));
            QVERIFY2(f.store->problems().front().contains(QStringLiteral("broken.geojson")), qPrintable(f.store->problems().front()));
            QCOMPARE(f.store->count(), 1);
            // Loaded again: replaced, not doubled.
            QVERIFY(f.store->loadFile(path("zones.geojson")));
            QCOMPARE(f.store->count(), 1);
        }
        Fixture again(m_dir.path());
        QCOMPARE(again.store->files(), QStringList{path("zones.geojson")});
        QCOMPARE(again.store->count(), 1);
        again.store->removeFile(path("zones.geojson"));
        QCOMPARE(again.store->count(), 0);
        Fixture third(m_dir.path());
        QCOMPARE(third.store->count(), 0);
    }

    void everySourceInOneSetInRowOrder()
    {
        Fixture f(m_dir.path());
        Route withFence = lineRoute();
        withFence.fence.polygons.push_back({{{56.94, 24.09}, {56.94, 24.2}, {56.96, 24.2}, {56.96, 24.09}}, true});
        f.model.resetRoute(withFence);
        QCOMPARE(f.store->count(), 1);
        QCOMPARE(f.store->groupOf(0), Airspace::Group::RouteFence);
        QCOMPARE(f.store->zoneAt(0).kind, ZoneKind::Inclusion);

        Zone aerodrome;
        aerodrome.name = QStringLiteral("EVRA");
        aerodrome.source = ZoneSource::ServerAerodrome;
        aerodrome.shape = ZoneCircle{{56.9236, 23.9711}, 5000};
        f.store->setServerZones({aerodrome});
        f.store->editor()->addCircle(at(3000, 0), 100);
        QCOMPARE(f.store->count(), 3);
        QCOMPARE(f.store->groupOf(0), Airspace::Group::Custom);
        QCOMPARE(f.store->groupOf(1), Airspace::Group::Server);
        QCOMPARE(f.store->groupOf(2), Airspace::Group::RouteFence);
        QCOMPARE(f.store->zones()->index(1).data(ZoneListModel::SourceRole).toString(), QStringLiteral("server aerodrome"));
        QCOMPARE(f.store->zones()->index(2).data(ZoneListModel::SourceRole).toString(), QStringLiteral("route fence"));

        // The route's fence follows the route: another route without one drops it.
        f.model.resetRoute(lineRoute());
        QCOMPARE(f.store->count(), 2);
        // A server zone switched off stays off when the server sends its zones again.
        f.store->setActive(1, false);
        f.store->setServerZones({aerodrome});
        QVERIFY(!f.store->zoneAt(1).active);
        // One whose ring crosses itself is kept and listed with the reason, not checked.
        Zone bowTie;
        bowTie.name = QStringLiteral("Bow tie");
        bowTie.source = ZoneSource::ServerCustom;
        bowTie.shape = ZonePolygons{{ZonePolygon{{{{56.95, 24.10}, {56.96, 24.12}, {56.96, 24.10}, {56.95, 24.12}}}}}};
        f.store->setServerZones({aerodrome, bowTie});
        QCOMPARE(f.store->count(), 3);
        QVERIFY(!f.store->zoneAt(2).active);
        QVERIFY2(!f.store->problemOf(2).isEmpty(), "no reason given");
        QCOMPARE(f.store->zones()->index(2).data(ZoneListModel::ProblemRole).toString(), f.store->problemOf(2));
        QVERIFY(f.store->problemOf(1).isEmpty());
    }

    void drawnZonesAreKeptAcrossRestarts()
    {
        const QString file = path("drawn-zones.geojson");
        {
            Fixture f(m_dir.path(), file);
            f.store->editor()->addPolygon(squareOverLeg2());
            f.store->editor()->addCircle(at(3000, 0), 120);
            QVERIFY(f.store->editor()->setName(1, QStringLiteral("Crane")));
            QVERIFY(f.store->editor()->setKind(1, QStringLiteral("inclusion")));
            QVERIFY(f.store->editor()->setLimits(1, QStringLiteral("10"), QStringLiteral("90"), QStringLiteral("AGL")));
            f.store->setActive(0, false);
        }
        Fixture f(m_dir.path(), file);
        QCOMPARE(f.store->count(), 2);
        const Zone &square = f.store->zoneAt(0), &crane = f.store->zoneAt(1);
        QCOMPARE(square.name, QStringLiteral("Zone 1"));
        QVERIFY(!square.active);
        QCOMPARE(std::get<ZonePolygons>(square.shape).parts.front().rings.front().size(), size_t(4));
        QCOMPARE(crane.name, QStringLiteral("Crane"));
        QCOMPARE(crane.kind, ZoneKind::Inclusion);
        QCOMPARE(std::get<ZoneCircle>(crane.shape).radius, 120.0);
        QCOMPARE(crane.floor, std::optional<HeightLimit>(HeightLimit{10, HeightReference::AboveTerrain}));
        QCOMPARE(crane.ceiling, std::optional<HeightLimit>(HeightLimit{90, HeightReference::AboveTerrain}));
        QCOMPARE(f.store->groupOf(1), Airspace::Group::Custom);

        // A file that cannot be read is kept aside, never overwritten by the next save.
        write("drawn-zones.geojson", "not json");
        Fixture broken(m_dir.path(), file);
        QCOMPARE(broken.store->count(), 0);
        QVERIFY(!broken.store->problems().isEmpty());
        const QStringList aside = QDir(m_dir.path()).entryList({QStringLiteral("drawn-zones.geojson.unreadable-*")});
        QCOMPARE(aside.size(), 1);
        QFile kept(m_dir.filePath(aside.front()));
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("not json"));
    }

    void eachEditIsOneUndoStep()
    {
        Fixture f(m_dir.path());
        ZoneEditor *editor = f.store->editor();
        QUndoStack *stack = editor->undoStack();
        editor->addPolygon(squareOverLeg2());
        QCOMPARE(stack->count(), 1);
        stack->undo();
        QCOMPARE(f.store->count(), 0);
        stack->redo();
        QCOMPARE(f.store->count(), 1);
        const Zone drawn = f.store->zoneAt(0);

        // A drag: many Continuing steps and the Done one are one undo step.
        for (int i = 1; i <= 5; ++i)
            QVERIFY(editor->moveVertex(0, 2, at(1600 + 10 * i, 100 + 10 * i), EditStep::Continuing));
        QVERIFY(editor->moveVertex(0, 2, at(1700, 200), EditStep::Done));
        QCOMPARE(stack->count(), 2);
        const GeoPoint moved = std::get<ZonePolygons>(f.store->zoneAt(0).shape).parts[0].rings[0][2];
        QVERIFY(std::abs(moved.latitude - at(1700, 200).latitude()) < 1e-12);
        // The next drag is a step of its own.
        QVERIFY(editor->moveVertex(0, 0, at(1300, -100), EditStep::Continuing));
        QVERIFY(editor->moveVertex(0, 0, at(1300, -150), EditStep::Done));
        QCOMPARE(stack->count(), 3);
        stack->undo();
        stack->undo();
        QCOMPARE(f.store->zoneAt(0), drawn);  // exactly as drawn
        stack->redo();
        QVERIFY(std::abs(std::get<ZonePolygons>(f.store->zoneAt(0).shape).parts[0].rings[0][2].latitude - moved.latitude) < 1e-12);
        stack->undo();

        // Corners added and removed; names, kinds and limits: one step each.
        QVERIFY(editor->insertVertex(0, 1, at(1500, -120)));
        QCOMPARE(std::get<ZonePolygons>(f.store->zoneAt(0).shape).parts[0].rings[0].size(), size_t(5));
        QVERIFY(editor->removeVertex(0, 1));
        QVERIFY(editor->setName(0, QStringLiteral("Works")));
        QVERIFY(editor->setKind(0, QStringLiteral("inclusion")));
        QVERIFY(editor->setLimits(0, 20.0, 80.0, QStringLiteral("AMSL")));
        QCOMPARE(stack->count(), 6);
        QCOMPARE(f.store->zones()->index(0).data(ZoneListModel::FloorRole).toString(), QStringLiteral("20 m AMSL"));
        QCOMPARE(editor->fields().name, QStringLiteral("Works"));

        // A circle: its centre is vertex 0; a radius drag merges.
        editor->addCircle(at(3000, 0), 100);
        QCOMPARE(f.store->selectedCustom(), 1);
        QCOMPARE(editor->radius(), 100.0);
        QCOMPARE(editor->figure().size(), 1);
        const int before = stack->count();
        QVERIFY(editor->setRadius(1, 150, EditStep::Continuing));
        QVERIFY(editor->setRadius(1, 180, EditStep::Continuing));
        QVERIFY(editor->setRadius(1, 200, EditStep::Done));
        QCOMPARE(stack->count(), before + 1);
        QCOMPARE(editor->radius(), 200.0);
        stack->undo();
        QCOMPARE(editor->radius(), 100.0);
        QVERIFY(editor->moveVertex(1, 0, at(3100, 0)));
        QVERIFY(std::abs(std::get<ZoneCircle>(f.store->zoneAt(1).shape).center.longitude - at(3100, 0).longitude()) < 1e-12);

        // Removed and back.
        QVERIFY(editor->removeZone(1));
        QCOMPARE(f.store->count(), 1);
        stack->undo();
        QCOMPARE(f.store->count(), 2);
    }

    void refusedEditsChangeNothing()
    {
        Fixture f(m_dir.path());
        ZoneEditor *editor = f.store->editor();
        QSignalSpy refused(editor, &ZoneEditor::refused);
        QCOMPARE(editor->addPolygon({at(0, 0), at(100, 0)}), -1);
        // A bow tie crosses itself.
        QCOMPARE(editor->addPolygon({at(0, 0), at(100, 100), at(100, 0), at(0, 100)}), -1);
        QCOMPARE(editor->addCircle(at(0, 0), 0), -1);
        QCOMPARE(f.store->count(), 0);
        editor->addPolygon(squareOverLeg2());
        editor->addPolygon({at(3000, 0), at(3100, 0), at(3050, 80)});
        const Zone drawn = f.store->zoneAt(0), triangle = f.store->zoneAt(1);
        const int steps = editor->undoStack()->count();
        refused.clear();
        QVERIFY(!editor->removeVertex(1, 0));                                               // three corners stay
        QVERIFY(!editor->moveVertex(0, 0, at(1700, 50)));                                   // would cross itself
        QVERIFY(!editor->setLimits(0, 90.0, 30.0, QStringLiteral("AMSL")));                 // ceiling under floor
        QVERIFY(!editor->setLimits(0, QStringLiteral("ten"), QString(), QStringLiteral("AMSL")));  // not a number
        QVERIFY(!editor->setLimits(0, 10.0, 30.0, QStringLiteral("QNH")));
        QVERIFY(!editor->setKind(0, QStringLiteral("forbidden")));
        QVERIFY(!editor->setName(0, QStringLiteral("  ")));
        QVERIFY(!editor->setRadius(0, 50));                                                 // a polygon has none
        QVERIFY(!editor->moveVertex(3, 0, at(0, 0)));                                       // no such zone
        QCOMPARE(refused.count(), 9);
        for (const QList<QVariant> &r : refused)
            QVERIFY(!r.front().toString().isEmpty());
        QCOMPARE(f.store->zoneAt(0), drawn);
        QCOMPARE(f.store->zoneAt(1), triangle);
        QCOMPARE(editor->undoStack()->count(), steps);
    }

    void theCustomFileIsGeoJsonAnyReaderTakes()
    {
        Zone z;
        z.name = QStringLiteral("Square");
        z.shape = ZonePolygons{{ZonePolygon{{{{56.9, 24.0}, {56.9, 24.1}, {57.0, 24.1}}}}}};
        z.ceiling = HeightLimit{120, HeightReference::AboveHome};
        const sortie::mission::Result<ZoneFile> read = readGeoJsonZones(customZonesJson({z}));
        QVERIFY(read.ok());
        QCOMPARE(read->zones.size(), size_t(1));
        QCOMPARE(read->zones[0].shape, z.shape);
        QCOMPARE(read->zones[0].ceiling, z.ceiling);
        QVERIFY(!read->zones[0].floor);
    }

    // The route's planned start and its authorisations are edits of the route: the client's check
    // follows them, and undo brings the finding back. A zone forbidden on weekend evenings over
    // leg 2 and an airfield needing an authorisation over leg 4 (ED-269).
    void theRoutesStartAndAuthorisationsAreEditsTheCheckFollows()
    {
        auto edBox = [](const char *id, const char *restriction, double from, double to, const char *applicability) {
            QStringList ring;
            for (const auto &[east, north] : {std::pair{from, -100.0}, {to, -100.0}, {to, 100.0}, {from, 100.0}, {from, -100.0}}) {
                const QGeoCoordinate c = at(east, north);
                ring << QStringLiteral("[%1, %2]").arg(c.longitude(), 0, 'f', 9).arg(c.latitude(), 0, 'f', 9);
            }
            return QStringLiteral(R"({"identifier": "%1", "country": "LVA", "name": "%1", "restriction": "%2", "zoneAuthority": [],
                "applicability": [%3], "geometry": [{"uomDimensions": "M", "lowerLimit": 0, "lowerVerticalReference": "AMSL",
                "upperLimit": 120, "upperVerticalReference": "AMSL", "horizontalProjection": {"type": "Polygon", "coordinates": [[%4]]}}]})")
                .arg(QLatin1String(id), QLatin1String(restriction), QLatin1String(applicability), ring.join(QStringLiteral(", ")));
        };
        write("ed269.json", (QStringLiteral(R"({"title": "test", "features": [)")
                             + edBox("LVP100", "PROHIBITED", 1400, 1600,
                                     R"({"permanent": "NO", "schedule": [{"day": ["SAT", "SUN"], "startTime": "18:00Z", "endTime": "23:00Z"}]})")
                             + QStringLiteral(", ") + edBox("LVA200", "REQ_AUTHORISATION", 3400, 3600, R"({"permanent": "YES"})")
                             + QStringLiteral("]}")).toUtf8());
        Fixture f(m_dir.path());
        QUndoStack stack;
        RouteEditor editor(&f.model, &stack);
        QVERIFY(f.store->loadFile(path("ed269.json")));
        // A Monday evening: only the airfield, which needs an authorisation.
        editor.setPlannedStart(QDateTime(QDate(2026, 6, 8), QTime(18, 30), QTimeZone::utc()));
        f.analyzer.recomputeNow();
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-exclusion")), 1);
        QVERIFY(firstMessage(f.analyzer.validation(), QStringLiteral("airspace-exclusion")).contains(QLatin1String("LVA200")));
        // A Saturday evening: the weekend zone too.
        editor.setPlannedStart(QDateTime(QDate(2026, 6, 6), QTime(18, 30), QTimeZone::utc()));
        f.analyzer.recomputeNow();
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-exclusion")), 2);
        // The airfield's authorisation recorded: a warning naming it.
        QVERIFY(editor.recordAuthorisation(QStringLiteral("LVA200"), QStringLiteral("LGS-2026-117")));
        QCOMPARE(f.model.authorisationFor(QStringLiteral("LVA200")), QStringLiteral("LGS-2026-117"));
        f.analyzer.recomputeNow();
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-exclusion")), 1);
        QVERIFY2(firstMessage(f.analyzer.validation(), QStringLiteral("airspace-authorised")).contains(QLatin1String("LGS-2026-117")),
                 qPrintable(firstMessage(f.analyzer.validation(), QStringLiteral("airspace-authorised"))));
        QVERIFY(!editor.recordAuthorisation(QStringLiteral("  "), QStringLiteral("X")));  // no identifier: refused
        // Undo, one step each: the authorisation goes, then the Saturday start.
        stack.undo();
        f.analyzer.recomputeNow();
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-exclusion")), 2);
        stack.undo();
        f.analyzer.recomputeNow();
        QCOMPARE(countRule(f.analyzer.validation(), QStringLiteral("airspace-exclusion")), 1);
        QCOMPARE(f.model.plannedStart(), QDateTime(QDate(2026, 6, 8), QTime(18, 30), QTimeZone::utc()));
    }
};

QTEST_MAIN(TstAirspaceStore)
#include "tst_airspacestore.moc"
