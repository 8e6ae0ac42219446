// UAS geographical zones where the operator plans (issue 33), offscreen with the program's own
// wiring against sortie-sim: an ED-269 file the test writes is loaded beside a route across two of
// its zones, one prohibited on weekend evenings only, one needing an authorisation. The map colours
// each by its restriction and shows the legend; the route planned for Saturday 18:00 (typed into the
// planned-start field) is refused for both, on Monday only for the authorisation; the weekend zone
// says it is not in force then; an authorisation recorded in the zone panel turns that error into a
// warning naming it, and the upload review shows it.
#include "Airspace.h"
#include "ClientWindow.h"
#include "MapPalette.h"
#include "MapView.h"
#include "MissionUploader.h"
#include "QuickScene.h"
#include "RouteAnalyzer.h"
#include "RouteDocument.h"
#include "RouteLayer.h"
#include "RouteModel.h"
#include "RoutePreparation.h"
#include "ZoneLayer.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QtQml/qqmlextensionplugin.h>

#include <cstdlib>
#include <ctime>

Q_IMPORT_QML_PLUGIN(Sortie_UiPlugin)

using namespace sortie;

namespace {

// The planned start is typed in the operator's time zone: the test's is UTC, set before Qt reads it.
const bool kInUtc = [] {
    qputenv("TZ", "UTC");
    tzset();
    return true;
}();

mission::Route lineRoute(const QGeoCoordinate &origin)
{
    mission::Route route;
    route.settings.name = QStringLiteral("Along the shore");
    for (int i = 0; i <= 4; ++i) {
        const QGeoCoordinate p = origin.atDistanceAndAzimuth(100.0 * i, 90);
        mission::Waypoint w;
        w.position = {p.latitude(), p.longitude()};
        w.altitude = 25;
        w.speed = 6;
        route.segments.push_back(w);
    }
    return route;
}

// An ED-269 feature: a circle of 40 m, from sea level up, unlimited.
QByteArray circleFeature(const QString &id, const QString &name, const QString &restriction, const QGeoCoordinate &centre,
                         const QByteArray &applicability)
{
    return QStringLiteral(R"({"identifier": "%1", "country": "LVA", "name": "%2", "type": "COMMON", "restriction": "%3",
        "reason": ["SENSITIVE"], "message": "Call the harbour master first", "applicability": [%4],
        "zoneAuthority": [{"name": "Harbour master", "phone": "+371 0000 0000", "purpose": "AUTHORIZATION"}],
        "geometry": [{"uomDimensions": "M", "lowerLimit": 0, "lowerVerticalReference": "AMSL", "upperLimit": 99999,
                      "upperVerticalReference": "AMSL",
                      "horizontalProjection": {"type": "Circle", "center": [%5, %6], "radius": 40}}]})")
        .arg(id, name, restriction, QString::fromUtf8(applicability))
        .arg(centre.longitude(), 0, 'f', 7)
        .arg(centre.latitude(), 0, 'f', 7)
        .toUtf8();
}

QPointF centreOf(QQuickItem *item)
{
    return item->mapToScene(QPointF(item->width() / 2, item->height() / 2));
}

// Pixels near `at` within `radius` that are `colour` (within 40).
int countNear(const QImage &image, QPointF at, int radius, const QColor &colour)
{
    int n = 0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const QPoint p = (at + QPointF(dx, dy)).toPoint();
            n += image.rect().contains(p) && test::colourDistance(image.pixel(p), colour.rgb()) < 40;
        }
    return n;
}

bool anyIssue(const mission::ValidationReport &report, mission::Severity severity, const QString &part)
{
    return std::any_of(report.issues.begin(), report.issues.end(),
                       [&](const mission::ValidationIssue &i) { return i.severity == severity && i.message.contains(part); });
}

QString issuesText(const mission::ValidationReport &report)
{
    QStringList lines;
    for (const mission::ValidationIssue &i : report.issues)
        lines << i.message;
    return lines.join(QLatin1Char('\n'));
}

} // namespace

class TestGeoZoneView : public QObject
{
    Q_OBJECT

    vehicle::Vehicle *emu101(test::ClientWindow &client) const
    {
        for (int r = 0; r < client.fleet().count(); ++r)
            if (client.fleet().vehicleAt(r)->name() == QStringLiteral("EMU-101"))
                return client.fleet().vehicleAt(r);
        return nullptr;
    }

    static int rowNamed(const airspace::Airspace &airspace, const QString &name)
    {
        for (int r = 0; r < airspace.count(); ++r)
            if (airspace.zoneAt(r).name == name)
                return r;
        return -1;
    }

    static void typeInto(QObject *field, const QString &text)
    {
        field->setProperty("text", text);
        QMetaObject::invokeMethod(field, "editingFinished");
    }

private slots:
    void initTestCase()
    {
        QVERIFY(kInUtc);
        test::useSoftwareRendering();
    }

    void theWeekendZoneCountsOnSaturdayAndTheAuthorisationIsKept()
    {
        test::ClientWindow client;
        QVERIFY2(client.isReady(), qPrintable(client.error()));
        QVERIFY(client.logIn());
        QTRY_VERIFY_WITH_TIMEOUT(emu101(client), 10000);
        vehicle::Vehicle *emu = emu101(client);
        client.showPage(1);
        client::RouteDocument *doc = client.missions().document();
        const QGeoCoordinate origin = emu->position().isValid() ? emu->position() : QGeoCoordinate(56.95, 24.1);
        doc->load(lineRoute(origin));
        QTRY_COMPARE(client.find<ui::RouteLayer>(QStringLiteral("routeLayer"))->count(), 5);
        int emuRow = -1;
        for (int r = 0; r < client.fleet().count(); ++r)
            if (client.fleet().vehicleAt(r) == emu)
                emuRow = r;
        client.find<QObject>(QStringLiteral("vehiclePicker"))->setProperty("currentIndex", emuRow);

        // The zone file: a weekend-evening prohibition at 150 m along the route, an authorisation zone at 300 m.
        const QGeoCoordinate weekend = origin.atDistanceAndAzimuth(150, 90), pier = origin.atDistanceAndAzimuth(300, 90);
        const QByteArray schedule = R"({"permanent": "NO", "startDateTime": "2026-01-01T00:00:00Z", "endDateTime": "2027-12-31T23:59:59Z",
                                        "schedule": [{"day": ["SAT", "SUN"], "startTime": "17:00:00.00Z", "endTime": "22:00:00.00Z"}]})";
        QTemporaryDir dir;
        QFile file(dir.filePath(QStringLiteral("latvia-ed269.json")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{\"title\": \"Written for tst_geozoneview\", \"features\": [" +
                   circleFeature(QStringLiteral("LVP001"), QStringLiteral("Weekend field"), QStringLiteral("PROHIBITED"), weekend, schedule) + ",\n" +
                   circleFeature(QStringLiteral("LVA002"), QStringLiteral("Pier approach"), QStringLiteral("REQ_AUTHORISATION"), pier,
                                 R"({"permanent": "YES"})") +
                   "]}");
        file.close();
        airspace::Airspace &airspace = client.graph().airspace();
        QVERIFY(airspace.loadFile(file.fileName()));
        QVERIFY2(airspace.problems().isEmpty(), qPrintable(airspace.problems().join(QLatin1Char('\n'))));
        // Rows by name when used: the server's zones around the map come and go above the file's.
        const auto weekendRow = [&airspace] { return rowNamed(airspace, QStringLiteral("Weekend field")); };
        const auto pierRow = [&airspace] { return rowNamed(airspace, QStringLiteral("Pier approach")); };
        QVERIFY(weekendRow() >= 0 && pierRow() >= 0);
        QTRY_VERIFY(client.find(QStringLiteral("zoneLegend"))->isVisible());

        // Saturday 18:00, typed as the operator types it: both zones refuse the route.
        QObject *start = client.find<QObject>(QStringLiteral("plannedStartField"));
        QVERIFY(start);
        typeInto(start, QStringLiteral("2026-12-05 18:00"));
        QTRY_COMPARE(doc->model()->plannedStart(), QDateTime(QDate(2026, 12, 5), QTime(18, 0), QTimeZone::utc()));
        QCOMPARE(start->property("text").toString(), QStringLiteral("2026-12-05 18:00"));
        const mission::RouteAnalyzer &analyzer = *doc->analyzer();
        QTRY_VERIFY2_WITH_TIMEOUT(anyIssue(analyzer.validation(), mission::Severity::Error, QStringLiteral("Weekend field"))
                                      && anyIssue(analyzer.validation(), mission::Severity::Error, QStringLiteral("none is recorded")),
                                  qPrintable(issuesText(analyzer.validation())), 10000);

        // On the map: each zone's edge in its restriction's colour.
        auto *map = client.page("missionPage")->property("map").value<ui::MapView *>();
        map->fitBounds(origin.latitude() - 0.0012, origin.longitude() - 0.0005, origin.latitude() + 0.0012,
                       origin.atDistanceAndAzimuth(400, 90).longitude() + 0.0005, 60);
        const ui::MapPalette &colours = map->colours();
        const auto edgeOf = [map](const QGeoCoordinate &centre) { return map->mapToScene(map->fromCoordinate(centre.atDistanceAndAzimuth(40, 0))); };
        QVERIFY(test::waitForFrame(client.window()));
        QImage shot = client.window()->grabWindow();
        QVERIFY2(countNear(shot, edgeOf(weekend), 3, colours.exclusion) > 0, "the prohibited zone's edge is not red");
        QVERIFY2(countNear(shot, edgeOf(pier), 3, colours.authorisation) > 0, "the authorisation zone's edge is not amber");
        QCOMPARE(countNear(shot, edgeOf(pier), 3, colours.exclusion), 0);

        // Monday 18:00: the weekend zone is not in force, and says so; the other still refuses.
        typeInto(start, QStringLiteral("2026-12-07 18:00"));
        QTRY_VERIFY2_WITH_TIMEOUT(!anyIssue(analyzer.validation(), mission::Severity::Error, QStringLiteral("Weekend field"))
                                      && anyIssue(analyzer.validation(), mission::Severity::Error, QStringLiteral("none is recorded")),
                                  qPrintable(issuesText(analyzer.validation())), 10000);
        QVERIFY(!airspace.appliesToFlight(weekendRow()));
        QVERIFY(airspace.appliesToFlight(pierRow()));
        airspace.setSelectedZone(weekendRow());
        QVERIFY(airspace.selectedGeoZone().valid);
        QVERIFY(!airspace.selectedGeoZone().inForce);
        QVERIFY2(airspace.selectedGeoZone().text.contains(QStringLiteral("Not in force")), qPrintable(airspace.selectedGeoZone().text));
        auto *zones = client.find<ui::ZoneLayer>(QStringLiteral("missionZoneLayer"));
        QVERIFY(zones);
        zones->hoverAt(map->mapToScene(map->fromCoordinate(weekend)) - zones->mapToScene(QPointF(0, 0)));
        QVERIFY2(zones->hoverText().contains(QStringLiteral("Not in force during the planned flight"))
                     && zones->hoverText().contains(QStringLiteral("Call the harbour master first")),
                 qPrintable(zones->hoverText()));
        zones->hoverAt(QPointF(-10, -10));

        // The authorisation, recorded in the zone panel for the chosen zone: the error becomes a
        // warning that names it, one undo step of the route.
        airspace.setSelectedZone(pierRow());
        client.find(QStringLiteral("zonePanel"))->setVisible(true); // as the "Zones" button opens it
        QQuickItem *details = client.find(QStringLiteral("geoZoneDetails"));
        QTRY_VERIFY(details->isVisible());
        QVERIFY2(client.find<QObject>(QStringLiteral("geoZoneRestriction"))->property("text").toString().contains(QStringLiteral("Authorisation needed")),
                 qPrintable(client.find<QObject>(QStringLiteral("geoZoneRestriction"))->property("text").toString()));
        const int steps = doc->undoStack()->count();
        client.find<QObject>(QStringLiteral("authorisationField"))->setProperty("text", QStringLiteral("RIGA-2026-77"));
        QQuickItem *record = client.find(QStringLiteral("recordAuthorisationButton"));
        QTRY_VERIFY(record->isVisible() && record->isEnabled());
        QMetaObject::invokeMethod(record, "clicked");
        QTRY_COMPARE(doc->model()->authorisationFor(QStringLiteral("LVA002")), QStringLiteral("RIGA-2026-77"));
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QTRY_VERIFY2_WITH_TIMEOUT(analyzer.validation().errorCount() == 0
                                      && anyIssue(analyzer.validation(), mission::Severity::Warning, QStringLiteral("under authorisation RIGA-2026-77")),
                                  qPrintable(issuesText(analyzer.validation())), 10000);
        QCOMPARE(airspace.selectedGeoZone().authorisation, QStringLiteral("RIGA-2026-77"));

        // The upload review lists it before anything is sent.
        client::MissionUploader *uploader = client.missions().preparation()->uploader();
        QQuickItem *upload = client.find(QStringLiteral("uploadButton"));
        QTRY_VERIFY(upload->isVisible() && upload->isEnabled());
        QTest::mouseClick(client.window(), Qt::LeftButton, {}, centreOf(upload).toPoint());
        QTRY_VERIFY_WITH_TIMEOUT(uploader->isAsking(), 15000);
        QTRY_VERIFY(client.find<QObject>(QStringLiteral("uploadQuestion"))->property("opened").toBool());
        const QString question = client.find<QObject>(QStringLiteral("uploadQuestionText"))->property("text").toString();
        QVERIFY2(question.contains(QStringLiteral("RIGA-2026-77")), qPrintable(question));
        uploader->cancel();
        QVERIFY(emu->mission().empty());
    }
};

QTEST_MAIN(TestGeoZoneView)
#include "tst_geozoneview.moc"
