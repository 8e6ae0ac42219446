// The route's server zone checks (checkAerodromeNfz / checkCustomNfz, HCI Route fields 23/24): kept
// through the HCI mapping both ways and in .sortie (a file without them reads as off, the server's
// reading of an absent flag), edited with one undo step each, shown by the model and the diff.
#include "Domain.pb.h"
#include "HciRouteMapper.h"
#include "RouteDiff.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "SortieFormat.h"

#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>

using namespace sortie::mission;
using sortie::mission::formats::readSortie;
using sortie::mission::formats::writeSortie;
namespace pb = com::ugcs::ucs::proto;

namespace {
Route twoWaypoints(bool aerodrome, bool custom)
{
    Route r;
    r.settings.name = QStringLiteral("flags");
    r.settings.checkAerodromeNfz = aerodrome;
    r.settings.checkCustomNfz = custom;
    for (double lat : {56.976, 56.978}) {
        Waypoint w;
        w.position = {lat, 24.073};
        r.segments.push_back(w);
    }
    return r;
}
} // namespace

class TestRouteNfzFlags : public QObject
{
    Q_OBJECT

private slots:
    void hciBothWays_data()
    {
        QTest::addColumn<bool>("aerodrome");
        QTest::addColumn<bool>("custom");
        QTest::newRow("neither") << false << false;
        QTest::newRow("aerodrome") << true << false;
        QTest::newRow("custom") << false << true;
        QTest::newRow("both") << true << true;
    }
    void hciBothWays()
    {
        QFETCH(bool, aerodrome);
        QFETCH(bool, custom);
        const pb::Route wire = routeToHci(twoWaypoints(aerodrome, custom));
        QVERIFY(wire.has_checkaerodromenfz() && wire.has_checkcustomnfz());  // a new route says both
        QCOMPARE(wire.checkaerodromenfz(), aerodrome);
        QCOMPARE(wire.checkcustomnfz(), custom);
        const auto back = routeFromHci(wire);
        QVERIFY(back);
        QCOMPARE(back->route.settings.checkAerodromeNfz, aerodrome);
        QCOMPARE(back->route.settings.checkCustomNfz, custom);
    }

    void aServerRouteKeepsWhatItSent()
    {
        pb::Route server = routeToHci(twoWaypoints(false, false));
        server.set_id(4);
        server.clear_checkcustomnfz();  // the server sent no custom flag
        server.set_checkaerodromenfz(true);
        auto read = routeFromHci(server);
        QVERIFY(read);
        QCOMPARE(read->route.settings.checkCustomNfz, false);  // absent reads as off
        QVERIFY(!routeToHci(read->route).has_checkcustomnfz());  // unedited: still absent
        Route route = read->route;
        route.settings.checkCustomNfz = true;
        const pb::Route edited = routeToHci(route);
        QVERIFY(edited.checkcustomnfz());
        QVERIFY(edited.checkaerodromenfz());
    }

    void sortieFile()
    {
        Mission m;
        m.name = QStringLiteral("m");
        m.routes.push_back(twoWaypoints(true, false));
        m.routes.push_back(twoWaypoints(false, true));
        const QByteArray bytes = writeSortie(m);
        QVERIFY(bytes.contains("\"checkAerodromeNfz\": true") || bytes.contains("\"checkAerodromeNfz\":true"));
        const auto back = readSortie(bytes);
        QVERIFY2(back, qPrintable(back ? QString() : back.error().toString()));
        QCOMPARE(back->routes[0].settings.checkAerodromeNfz, true);
        QCOMPARE(back->routes[0].settings.checkCustomNfz, false);
        QCOMPARE(back->routes[1].settings.checkAerodromeNfz, false);
        QCOMPARE(back->routes[1].settings.checkCustomNfz, true);
        QCOMPARE(writeSortie(*back), bytes);  // stable

        // A file written before the flags: both off. A flag that is not true/false is an error naming it.
        QByteArray old = bytes;
        old.replace("\"checkAerodromeNfz\": true,", "").replace("\"checkAerodromeNfz\":true,", "");
        QVERIFY(!old.contains("\"checkAerodromeNfz\": true"));
        const auto oldRead = readSortie(old);
        QVERIFY2(oldRead, qPrintable(oldRead ? QString() : oldRead.error().toString()));
        QCOMPARE(oldRead->routes[0].settings.checkAerodromeNfz, false);
        QByteArray bad = bytes;
        bad.replace("\"checkCustomNfz\": true", "\"checkCustomNfz\": \"yes\"");
        const auto badRead = readSortie(bad);
        QVERIFY(!badRead);
        QVERIFY2(badRead.error().toString().contains(QStringLiteral("checkCustomNfz")), qPrintable(badRead.error().toString()));
    }

    void editedWithOneUndoStepEach()
    {
        RouteModel model;
        QUndoStack stack;
        RouteEditor editor(&model, &stack);
        model.resetRoute(twoWaypoints(false, false));
        QSignalSpy changed(&model, &RouteModel::settingsChanged);
        editor.setCheckAerodromeNfz(true);
        QCOMPARE(model.property("checkAerodromeNfz").toBool(), true);
        QCOMPARE(model.property("checkCustomNfz").toBool(), false);
        QCOMPARE(stack.count(), 1);
        QCOMPARE(stack.undoText(), QStringLiteral("Check aerodrome zones"));
        editor.setCheckAerodromeNfz(true);  // no change, no step
        QCOMPARE(stack.count(), 1);
        editor.setCheckCustomNfz(true);
        QCOMPARE(stack.count(), 2);
        QVERIFY(model.checkCustomNfz());
        QVERIFY(changed.count() >= 2);
        stack.undo();
        QVERIFY(!model.checkCustomNfz());
        QVERIFY(model.checkAerodromeNfz());
        stack.undo();
        QVERIFY(!model.checkAerodromeNfz());
        stack.redo();
        QVERIFY(model.checkAerodromeNfz());
    }

    void theDiffSaysSo()
    {
        const auto diff = RouteDiff::compare(twoWaypoints(false, true), twoWaypoints(true, true));
        QCOMPARE(diff.texts(), QStringList{QStringLiteral("aerodrome zone check on")});
    }
};

QTEST_GUILESS_MAIN(TestRouteNfzFlags)
#include "tst_routenfzflags.moc"
