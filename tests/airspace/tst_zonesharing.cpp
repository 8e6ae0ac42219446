// Drawn zones and the server's custom zones meeting (ZoneSharing) against sortie-sim's HCI server
// over 127.0.0.1, through the client's own zone store: a drawn zone sent to the server is listed
// once, as the server's; a server zone edited here is drawn once (the copy) and sent back under its
// lock as its next version, which a second operator sees; a copy of a version another operator
// replaced is not sent; a delete goes through; aerodromes are refused; the chosen zone stays chosen
// while rows move; a copy is remembered with its server id across restarts.
#include "Airspace.h"
#include "HciClient.h"
#include "HciServer.h"
#include "HciSession.h"
#include "RouteAnalyzer.h"
#include "RouteModel.h"
#include "ServerZoneReply.h"
#include "ServerZones.h"
#include "SimWorld.h"
#include "ZoneEditor.h"
#include "ZoneOperator.h"
#include "ZoneSharing.h"

#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace sortie;
using namespace sortie::airspace;
using namespace sortie::airspace::test;

namespace {

struct Desk
{
    QSettings settings;
    mission::RouteModel route;
    mission::RouteAnalyzer analyzer{&route};
    Airspace store;
    ZoneSharing sharing;

    Desk(const QString &dir, ServerZones &server, const QString &customFile = {})
        : settings(dir + QStringLiteral("/settings.ini"), QSettings::IniFormat)
        , store(&settings, &analyzer, &route, nullptr, customFile)
        , sharing(&store, &server)
    {
        store.setServerZones(server.zones());
        QObject::connect(&server, &ServerZones::zonesChanged, &store, [this, &server] { store.setServerZones(server.zones()); });
    }
    // Rows listing `name`.
    QList<int> rowsOf(const QString &name) const
    {
        QList<int> rows;
        for (int r = 0; r < store.count(); ++r)
            if (store.zoneAt(r).name == name)
                rows << r;
        return rows;
    }
    // Waits for the operation started to end; its outcome.
    bool finish()
    {
        QSignalSpy done(&sharing, &ZoneSharing::finished);
        if (!done.wait(kWait))
            return false;
        return done.first().at(0).toBool();
    }
};

QList<QGeoCoordinate> pierCorners()
{
    return {{56.9600, 24.0300}, {56.9600, 24.0340}, {56.9625, 24.0340}, {56.9625, 24.0300}};
}

} // namespace

class TestZoneSharing : public QObject
{
    Q_OBJECT

    std::unique_ptr<TwoOperatorServer> m_sim;
    QTemporaryDir m_dir;

    quint16 port() const { return m_sim->port(); }

private slots:
    void init() { m_sim = std::make_unique<TwoOperatorServer>(); }
    void cleanup() { m_sim.reset(); }

    void aDrawnZoneSentIsListedOnceAsTheServers()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        Desk desk(m_dir.path(), admin.zones);
        const int zonesBefore = desk.store.count();
        QCOMPARE(desk.store.editor()->addPolygon(pierCorners()), 0);
        QVERIFY(desk.store.editor()->setLimits(0, QVariant(), 60, QStringLiteral("AGL")));
        QVERIFY(desk.sharing.canSend());
        QVERIFY(!desk.sharing.sendUpdates());
        QSignalSpy answered(&admin.zones, &ServerZones::answered);
        QVERIFY(desk.sharing.send(0));
        QVERIFY(desk.sharing.isBusy());
        QVERIFY(!desk.sharing.send(0));  // one at a time
        QVERIFY2(desk.finish(), qPrintable(desk.sharing.status()));
        QCOMPARE(desk.sharing.status(), QStringLiteral("Zone 'Zone 1' is on the server."));
        QVERIFY(desk.store.customZones().empty());
        QVERIFY(answered.count() > 0 || answered.wait(kWait));
        // Once: the server's, a custom zone with its id, and still the chosen one.
        const QList<int> rows = desk.rowsOf(QStringLiteral("Zone 1"));
        QCOMPARE(rows.size(), 1);
        QCOMPARE(desk.store.groupOf(rows[0]), Airspace::Group::Server);
        QCOMPARE(desk.store.zoneAt(rows[0]).source, ZoneSource::ServerCustom);
        QVERIFY(desk.store.zoneAt(rows[0]).serverId);
        QCOMPARE(desk.store.zoneAt(rows[0]).ceiling, std::optional(HeightLimit{60, terrain::HeightReference::AboveTerrain}));
        QCOMPARE(desk.store.count(), zonesBefore + 1);
        QCOMPARE(desk.store.selectedZone(), rows[0]);
        QVERIFY(desk.sharing.canEditOnServer());
        // Undo brings the draft back (not the server's change): listed twice then, drawn and stored.
        desk.store.editor()->undo();
        QCOMPARE(desk.store.customZones().size(), size_t(1));
        QVERIFY(!desk.store.customZones()[0].serverId);
        QCOMPARE(desk.rowsOf(QStringLiteral("Zone 1")).size(), 2);
    }

    void aServerZoneEditedHereIsSentBackAsItsNextVersion()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        Operator bob(port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        Desk desk(m_dir.path(), admin.zones);
        const int zonesBefore = desk.store.count();
        const QList<int> crane = desk.rowsOf(QStringLiteral("Crane works"));
        QCOMPARE(crane.size(), 1);
        const Zone original = desk.store.zoneAt(crane[0]);
        desk.store.setSelectedZone(crane[0]);
        QVERIFY(desk.sharing.canEditOnServer());
        QVERIFY(desk.sharing.editCopy(crane[0]));
        // The copy is drawn, chosen, and the server's zone is not listed beside it.
        QCOMPARE(desk.store.customZones().size(), size_t(1));
        QCOMPARE(desk.store.customZones()[0].serverId, original.serverId);
        QCOMPARE(desk.store.rowOfServerZone(*original.serverId), -1);
        QCOMPARE(desk.rowsOf(QStringLiteral("Crane works")), QList<int>{0});
        QCOMPARE(desk.store.count(), zonesBefore);
        QCOMPARE(desk.store.selectedCustom(), 0);
        QVERIFY(desk.sharing.sendUpdates());

        QVERIFY(desk.store.editor()->setLimits(0, QVariant(), 80, QStringLiteral("AGL")));
        QSignalSpy bobSaw(&bob.zones, &ServerZones::answered);
        QVERIFY(desk.sharing.send(0));
        QVERIFY2(desk.finish(), qPrintable(desk.sharing.status()));
        QVERIFY(desk.store.customZones().empty());
        QVERIFY(QTest::qWaitFor([&] {
            const int row = desk.store.rowOfServerZone(*original.serverId);
            return row >= 0 && desk.store.zoneAt(row).serverVersion > original.serverVersion;
        }, kWait));
        const int row = desk.store.rowOfServerZone(*original.serverId);
        QCOMPARE(desk.store.zoneAt(row).ceiling, std::optional(HeightLimit{80, terrain::HeightReference::AboveTerrain}));
        QCOMPARE(desk.rowsOf(QStringLiteral("Crane works")).size(), 1);
        QCOMPARE(desk.store.selectedZone(), row);
        // The other operator sees the new version (EET_NFZ_UPDATED).
        QVERIFY(QTest::qWaitFor([&] {
            const Zone *z = bob.find(QStringLiteral("Crane works"));
            return z && z->ceiling == std::optional(HeightLimit{80, terrain::HeightReference::AboveTerrain});
        }, kWait));
        QVERIFY(!m_sim->world->locks().holder(QStringLiteral("NoFlightZone"), *original.serverId));
    }

    void aCopyOfAReplacedVersionIsNotSent()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        Operator bob(port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        Desk desk(m_dir.path(), admin.zones);
        const int crane = desk.rowsOf(QStringLiteral("Crane works")).value(0, -1);
        QVERIFY(crane >= 0);
        const Zone original = desk.store.zoneAt(crane);
        QVERIFY(desk.sharing.editCopy(crane));

        // Bob changes the zone meanwhile; admin's client hears of it.
        Zone bobs = *bob.find(QStringLiteral("Crane works"));
        bobs.ceiling = HeightLimit{45, terrain::HeightReference::AboveTerrain};
        bool bobDone = false;
        ServerZoneReply *reply = bob.zones.save(bobs);
        connect(reply, &ServerZoneReply::finished, this, [&] { bobDone = reply->isOk(); });
        QVERIFY(QTest::qWaitFor([&] { return bobDone; }, kWait));
        QVERIFY(QTest::qWaitFor([&] {
            const Zone *z = admin.find(QStringLiteral("Crane works"));
            return z && z->serverVersion > original.serverVersion;
        }, kWait));

        QVERIFY(!desk.sharing.send(0));
        QVERIFY(desk.sharing.hasFailed());
        QVERIFY2(desk.sharing.status().contains(QStringLiteral("was changed on the server since you copied it")), qPrintable(desk.sharing.status()));
        QCOMPARE(desk.store.customZones().size(), size_t(1));  // the operator's copy is kept
        // Discarding the copy brings the server's (Bob's) version back.
        QVERIFY(desk.store.editor()->removeZone(0));
        const int row = desk.store.rowOfServerZone(*original.serverId);
        QVERIFY(row >= 0);
        QCOMPARE(desk.store.zoneAt(row).ceiling, std::optional(HeightLimit{45, terrain::HeightReference::AboveTerrain}));
    }

    void aCustomZoneIsDeletedAndAnAerodromeIsNot()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        Desk desk(m_dir.path(), admin.zones);
        const int rix = desk.rowsOf(QStringLiteral("RIX CTR")).value(0, -1);
        QVERIFY(rix >= 0);
        desk.store.setSelectedZone(rix);
        QVERIFY(!desk.sharing.canEditOnServer());
        QVERIFY(!desk.sharing.removeFromServer(rix));
        QVERIFY(!desk.sharing.editCopy(rix));
        QVERIFY(desk.sharing.status().contains(QStringLiteral("aerodrome zones are the server's own")));

        const int crane = desk.rowsOf(QStringLiteral("Crane works")).value(0, -1);
        QVERIFY(desk.sharing.removeFromServer(crane));
        QVERIFY2(desk.finish(), qPrintable(desk.sharing.status()));
        QCOMPARE(desk.sharing.status(), QStringLiteral("Zone 'Crane works' was deleted on the server."));
        QVERIFY(QTest::qWaitFor([&] { return desk.rowsOf(QStringLiteral("Crane works")).isEmpty(); }, kWait));
        // Still chosen: RIX CTR, although the rows moved under it.
        QCOMPARE(desk.store.zoneName(desk.store.selectedZone()), QStringLiteral("RIX CTR"));
    }

    void theChosenZoneStaysChosenWhileRowsMove()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        Desk desk(m_dir.path(), admin.zones);
        QFile file(m_dir.filePath(QStringLiteral("pier.geojson")));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"name":"Pier"},
            "geometry":{"type":"Point","coordinates":[24.03,56.96]}, "properties":{"name":"Pier","radius":50}}]})");
        file.close();
        QVERIFY(desk.store.loadFile(file.fileName()));
        const int pier = desk.rowsOf(QStringLiteral("Pier")).value(0, -1);
        QVERIFY(pier >= 0);
        desk.store.setSelectedZone(pier);
        QSignalSpy moved(&desk.store, &Airspace::selectedZoneChanged);
        // A zone the server lists from now on, above the file's rows.
        Zone more;
        more.name = QStringLiteral("Mast");
        more.source = ZoneSource::ServerCustom;
        more.shape = ZoneCircle{{56.97, 24.05}, 40};
        bool done = false;
        ServerZoneReply *reply = admin.zones.save(more);
        connect(reply, &ServerZoneReply::finished, this, [&] { done = reply->isOk(); });
        QVERIFY(QTest::qWaitFor([&] { return done && !desk.rowsOf(QStringLiteral("Mast")).isEmpty(); }, kWait));
        QCOMPARE(desk.rowsOf(QStringLiteral("Pier")), QList<int>{pier + 1});
        QCOMPARE(desk.store.selectedZone(), pier + 1);
        QVERIFY(moved.count() >= 1);
    }

    void aCopyKeepsItsServerIdAcrossRestarts()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        const QString drawn = m_dir.filePath(QStringLiteral("drawn.geojson"));
        std::optional<int> id;
        {
            Desk desk(m_dir.path(), admin.zones, drawn);
            const int crane = desk.rowsOf(QStringLiteral("Crane works")).value(0, -1);
            QVERIFY(desk.sharing.editCopy(crane));
            id = desk.store.customZones()[0].serverId;
            QVERIFY(id);
        }
        Desk again(m_dir.path(), admin.zones, drawn);
        QCOMPARE(again.store.customZones().size(), size_t(1));
        QCOMPARE(again.store.customZones()[0].serverId, id);
        QCOMPARE(again.store.rowOfServerZone(*id), -1);  // still drawn once
        QCOMPARE(again.rowsOf(QStringLiteral("Crane works")).size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestZoneSharing)
#include "tst_zonesharing.moc"
