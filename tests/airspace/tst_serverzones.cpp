// The server's no-fly zones against sortie-sim's HCI server (in-process, over 127.0.0.1):
// ServerZones lists both types for the view box, creates, edits and deletes a custom zone under
// its lock, and a second client sees every change through EET_NFZ_UPDATED; a lock another
// operator holds refuses the edit by name; ProcessRoute refuses a route crossing a zone its flags
// ask about, naming the zone, and accepts it otherwise.
#include "HciClient.h"
#include "HciReply.h"
#include "HciRouteMapper.h"
#include "HciServer.h"
#include "HciSession.h"
#include "Messages.pb.h"
#include "ServerZones.h"
#include "SimWorld.h"
#include "ZoneOperator.h"

#include <QSignalSpy>
#include <QTest>

#include <memory>
#include <numbers>

using namespace sortie;
using namespace sortie::airspace;
using namespace sortie::airspace::test;
namespace pb = com::ugcs::ucs::proto;

namespace {

constexpr double kRad = std::numbers::pi / 180.0;

// Waits for a save or delete to finish; the reply is gone afterwards, so its outcome is copied.
struct Outcome
{
    bool ok = false;
    QString error;
    std::optional<Zone> zone;
};

Outcome await(ServerZoneReply *reply)
{
    Outcome out;
    bool done = false;
    QObject::connect(reply, &ServerZoneReply::finished, [&] {
        done = true;
        out = {reply->isOk(), reply->error(), reply->zone()};
    });
    if (!QTest::qWaitFor([&] { return done; }, kWait))
        out.error = QStringLiteral("(the test waited in vain for the reply)");
    return out;
}

// A request's reply once it finished (or timed out: then it fails).
template<class Response>
std::unique_ptr<hci::HciReply> answer(hci::HciReply *reply)
{
    reply->setAutoDelete(false);
    std::unique_ptr<hci::HciReply> owned(reply);
    (void)QTest::qWaitFor([&] { return owned->isFinished(); }, kWait);
    return owned;
}

Zone surveyHold()
{
    Zone z;
    z.name = QStringLiteral("Survey hold");
    z.source = ZoneSource::ServerCustom;
    z.shape = ZonePolygons{{ZonePolygon{{{{56.9800, 24.0650}, {56.9800, 24.0700}, {56.9830, 24.0700}, {56.9830, 24.0650}}}}}};
    z.ceiling = HeightLimit{100, HeightReference::AboveTerrain};
    return z;
}

// A two-waypoint route at one height AGL, with the server's zone checks as given.
pb::Route line(mission::GeoPoint from, mission::GeoPoint to, double agl, bool aerodrome, bool custom)
{
    mission::Route route;
    route.settings.name = QStringLiteral("line");
    route.settings.maxAltitude = 300;
    route.settings.checkAerodromeNfz = aerodrome;
    route.settings.checkCustomNfz = custom;
    for (const auto &p : {from, to}) {
        mission::Waypoint w;
        w.position = p;
        w.altitude = agl;
        route.segments.push_back(w);
    }
    return mission::routeToHci(route);
}

QStringList errorsOf(const pb::ProcessedRoute &processed, bool *allProcessed)
{
    QStringList errors;
    *allProcessed = true;
    for (const auto &s : processed.segments()) {
        *allProcessed = *allProcessed && s.status() == pb::RPS_PROCESSED;
        for (const auto &m : s.messageset().messages())
            if (m.severity() == pb::MS_ERROR)
                errors << QString::fromStdString(m.defaulttext());
    }
    return errors;
}

} // namespace

class TestServerZones : public QObject
{
    Q_OBJECT

    std::unique_ptr<TwoOperatorServer> m_sim;

    quint16 port() const { return m_sim->port(); }

    pb::ProcessedRoute processed(Operator &op, const pb::Route &route)
    {
        auto reply = answer<pb::ProcessRouteResponse>(op.client.processRoute(route));
        if (!reply->isOk())
            qWarning() << reply->error().toString();
        return reply->response<pb::ProcessRouteResponse>().processedroute();
    }

private slots:
    void init() { m_sim = std::make_unique<TwoOperatorServer>(); }
    void cleanup() { m_sim.reset(); }

    void bothTypesForTheViewBox()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(admin.zones.problems().isEmpty());
        QVERIFY(admin.zones.error().isEmpty());
        QCOMPARE(admin.zones.zones().size(), size_t(3));
        const Zone *rix = admin.find(QStringLiteral("RIX CTR"));
        const Zone *spilve = admin.find(QStringLiteral("Spilve airfield"));
        const Zone *works = admin.find(QStringLiteral("Crane works"));
        QVERIFY(rix && spilve && works);
        QCOMPARE(rix->source, ZoneSource::ServerAerodrome);
        QVERIFY(std::holds_alternative<ZoneConeFrustum>(rix->shape));
        QCOMPARE(rix->ceiling, std::optional(HeightLimit{600, HeightReference::Amsl}));
        QCOMPARE(spilve->source, ZoneSource::ServerAerodrome);
        QVERIFY(!spilve->floor);
        QCOMPARE(spilve->ceiling, std::optional(HeightLimit{150, HeightReference::AboveTerrain}));
        QCOMPARE(works->source, ZoneSource::ServerCustom);
        QVERIFY(works->serverId.has_value());

        // A box around the crane works: not Spilve, but RIX CTR, whose extent (8 km around the
        // airport) reaches it: the server answers by each zone's extent. One far away holds nothing.
        QSignalSpy answered(&admin.zones, &ServerZones::answered);
        admin.zones.setViewBox({56.9735, 24.0840, 56.9765, 24.0890, false});
        QVERIFY(answered.wait(kWait));
        QCOMPARE(admin.zones.zones().size(), size_t(2));
        QVERIFY(admin.find(QStringLiteral("Crane works")) && admin.find(QStringLiteral("RIX CTR")));
        admin.zones.setViewBox({10.0, 10.0, 10.1, 10.1, false});
        QVERIFY(answered.wait(kWait));
        QVERIFY(admin.zones.zones().empty());

        // The server filters by type.
        pb::GetNfzListRequest request;
        request.set_minlatitude(kDemoBox.south * kRad);
        request.set_minlongitude(kDemoBox.west * kRad);
        request.set_maxlatitude(kDemoBox.north * kRad);
        request.set_maxlongitude(kDemoBox.east * kRad);
        request.add_types(pb::NT_AERODROME);
        auto reply = answer<pb::GetNfzListResponse>(admin.session.send(request));
        QVERIFY2(reply->isOk(), qPrintable(reply->error().toString()));
        const auto &list = reply->response<pb::GetNfzListResponse>();
        QCOMPARE(list.zones_size(), 2);
        for (const auto &z : list.zones())
            QCOMPARE(z.type(), pb::NT_AERODROME);
    }

    void customZoneCreatedEditedDeletedSeenByASecondClient()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        Operator bob(port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        QSignalSpy bobAnswered(&bob.zones, &ServerZones::answered);

        const Outcome created = await(admin.zones.save(surveyHold()));
        QVERIFY2(created.ok, qPrintable(created.error));
        QVERIFY(created.zone && created.zone->serverId);
        const int id = *created.zone->serverId;
        QTRY_VERIFY_WITH_TIMEOUT(bob.find(QStringLiteral("Survey hold")), kWait);  // only EET_NFZ_UPDATED makes bob ask again
        QVERIFY(bobAnswered.count() >= 1);
        QCOMPARE(bob.find(QStringLiteral("Survey hold"))->ceiling, std::optional(HeightLimit{100, HeightReference::AboveTerrain}));

        Zone edited = *created.zone;
        edited.ceiling = HeightLimit{120, HeightReference::AboveTerrain};
        const Outcome saved = await(admin.zones.save(edited));
        QVERIFY2(saved.ok, qPrintable(saved.error));
        QCOMPARE(*saved.zone->serverId, id);
        QVERIFY(saved.zone->serverVersion > created.zone->serverVersion);
        QVERIFY(!m_sim->world->locks().holder(QStringLiteral("NoFlightZone"), id));  // released after the write
        QTRY_COMPARE_WITH_TIMEOUT(bob.find(QStringLiteral("Survey hold"))->ceiling,
                                  std::optional(HeightLimit{120, HeightReference::AboveTerrain}), kWait);

        const Outcome removed = await(admin.zones.remove(*saved.zone));
        QVERIFY2(removed.ok, qPrintable(removed.error));
        QVERIFY(!m_sim->world->store().find(QStringLiteral("NoFlightZone"), id));
        QTRY_VERIFY_WITH_TIMEOUT(!bob.find(QStringLiteral("Survey hold")), kWait);
        QTRY_VERIFY_WITH_TIMEOUT(!admin.find(QStringLiteral("Survey hold")), kWait);
    }

    void aLockAnotherOperatorHoldsRefusesTheEdit()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        Operator bob(port(), QStringLiteral("bob"), QStringLiteral("s3cret-bob"));
        const Outcome created = await(admin.zones.save(surveyHold()));
        QVERIFY2(created.ok, qPrintable(created.error));
        const int id = *created.zone->serverId;
        auto lock = answer<pb::AcquireLockResponse>(bob.client.acquireLock(hci::HciObjectType::NoFlightZone, id));
        QVERIFY2(lock->isOk(), qPrintable(lock->error().toString()));

        Zone edited = *created.zone;
        edited.name = QStringLiteral("Survey hold, wider");
        const Outcome refused = await(admin.zones.save(edited));
        QVERIFY(!refused.ok);
        qInfo().noquote() << "refused:" << refused.error;
        QVERIFY2(refused.error.startsWith(QStringLiteral("Zone 'Survey hold, wider' was not saved: it is locked")), qPrintable(refused.error));
        QVERIFY2(refused.error.contains(QStringLiteral("'bob'")), qPrintable(refused.error));
        const Outcome notDeleted = await(admin.zones.remove(*created.zone));
        QVERIFY(!notDeleted.ok);
        QVERIFY2(notDeleted.error.contains(QStringLiteral("was not deleted: it is locked")), qPrintable(notDeleted.error));
        const auto *stored = m_sim->world->store().find(QStringLiteral("NoFlightZone"), id);
        QVERIFY(stored);
        QCOMPARE(stored->noflightzone().name(), std::string("Survey hold"));  // nothing changed

        auto release = answer<pb::ReleaseLockResponse>(bob.client.releaseLock(hci::HciObjectType::NoFlightZone, id));
        QVERIFY(release->isOk());
        const Outcome saved = await(admin.zones.save(edited));
        QVERIFY2(saved.ok, qPrintable(saved.error));
        QCOMPARE(m_sim->world->store().find(QStringLiteral("NoFlightZone"), id)->noflightzone().name(), std::string("Survey hold, wider"));
    }

    // A zone the server holds but Sortie cannot check is left out and named; the rest stay.
    void anUnusableZoneIsLeftOutNamed()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        pb::DomainObjectWrapper w;
        auto *bad = w.mutable_noflightzone();
        bad->set_name("Two corners");
        bad->set_type(pb::NT_CUSTOM);
        for (double lat : {56.980, 56.981}) {
            auto *p = bad->mutable_prism()->add_points();
            p->set_latitude(lat * kRad);
            p->set_longitude(24.07 * kRad);
        }
        QSignalSpy changed(&admin.zones, &ServerZones::zonesChanged);
        const int id = hci::objectId(m_sim->world->store().save(QStringLiteral("NoFlightZone"), w, 0).object->noflightzone());
        QVERIFY(changed.wait(kWait));  // the store's change went out as EET_NFZ_UPDATED
        QCOMPARE(admin.zones.zones().size(), size_t(3));
        QCOMPARE(admin.zones.problems(),
                 QStringList{QStringLiteral("NoFlightZone %1 ('Two corners') was left out: its prism has 2 corner(s); a polygon needs 3").arg(id)});

        // Without a connection nothing is sent, and the caller is told.
        admin.session.close();
        QTRY_VERIFY(!admin.session.isReady());
        const Outcome offline = await(admin.zones.save(surveyHold()));
        QVERIFY(!offline.ok);
        QCOMPARE(offline.error, QStringLiteral("Zone 'Survey hold' was not saved: not connected to the server."));
        QCOMPARE(admin.zones.zones().size(), size_t(3));  // still the airspace while the line is down
    }

    void aerodromeZonesAreTheServers()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        const Zone rix = *admin.find(QStringLiteral("RIX CTR"));
        const Outcome refused = await(admin.zones.save(rix));
        QVERIFY(!refused.ok);
        QVERIFY2(refused.error.contains(QStringLiteral("aerodrome zones are the server's own")), qPrintable(refused.error));
        // The server refuses too, whoever asks.
        auto del = answer<pb::DeleteObjectResponse>(admin.client.deleteObject(hci::HciObjectType::NoFlightZone, *rix.serverId));
        QVERIFY(!del->isOk());
        QVERIFY2(del->error().message().contains(QStringLiteral("aerodrome")), qPrintable(del->error().message()));
        pb::NoFlightZone fake;
        fake.set_name("Mine");
        fake.set_type(pb::NT_AERODROME);
        fake.mutable_conefrustum()->set_baselatitude(56.95 * kRad);
        fake.mutable_conefrustum()->set_baselongitude(24.0 * kRad);
        fake.mutable_conefrustum()->set_baseradius(100);
        auto put = answer<pb::CreateOrUpdateObjectResponse>(admin.client.createOrUpdate(fake));
        QVERIFY(!put->isOk());
        QVERIFY2(put->error().message().contains(QStringLiteral("custom zones")), qPrintable(put->error().message()));
        // A zone that is no volume is refused, named.
        pb::NoFlightZone flat;
        flat.set_name("Flat");
        auto bad = answer<pb::CreateOrUpdateObjectResponse>(admin.client.createOrUpdate(flat));
        QVERIFY(!bad->isOk());
        QVERIFY2(bad->error().message().contains(QStringLiteral("'Flat' cannot be stored: it has no volume")), qPrintable(bad->error().message()));
    }

    void processRouteRefusesACrossingWhenAsked()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        // North from the pier over Spilve airfield (ground to 150 m AGL), at 50 m AGL.
        const mission::GeoPoint pier{56.9770, 24.0730}, north{56.9990, 24.0750};
        bool ok = false;
        QStringList errors = errorsOf(processed(admin, line(pier, north, 50, true, false)), &ok);
        QVERIFY(!ok);
        QCOMPARE(errors.size(), 1);
        qInfo().noquote() << "refused:" << errors[0];
        QVERIFY2(errors[0].startsWith(QStringLiteral("Segment 2: the route crosses the aerodrome no-fly zone 'Spilve airfield': Leg 1 enters "
                                                     "'Spilve airfield' from ")),
                 qPrintable(errors[0]));
        errors = errorsOf(processed(admin, line(pier, north, 50, false, true)), &ok);
        QVERIFY2(ok, qPrintable(errors.join('\n')));  // only custom zones asked about
        errors = errorsOf(processed(admin, line(pier, north, 200, true, true)), &ok);
        QVERIFY2(ok, qPrintable(errors.join('\n')));  // over its ceiling

        // East along the pier through the crane works (a custom zone, ground to 60 m AGL) at 40 m.
        const mission::GeoPoint west{56.9750, 24.0800}, east{56.9750, 24.0950};
        errors = errorsOf(processed(admin, line(west, east, 40, false, true)), &ok);
        QVERIFY(!ok);
        QVERIFY2(errors.size() == 1 && errors[0].contains(QStringLiteral("the custom no-fly zone 'Crane works'")), qPrintable(errors.join('\n')));
        errors = errorsOf(processed(admin, line(west, east, 40, true, false)), &ok);
        QVERIFY2(ok, qPrintable(errors.join('\n')));
    }

    void routeFlagsRoundTripThroughTheServer()
    {
        Operator admin(port(), QStringLiteral("admin"), QStringLiteral("admin"));
        const pb::DomainObjectWrapper *demo = nullptr;
        for (const auto *w : m_sim->world->store().list(QStringLiteral("Route")))
            demo = w;
        QVERIFY(demo);
        // The store's object is replaced by the save below: keep its id, not the pointer.
        const int demoId = demo->route().id();
        auto read = mission::routeFromHci(demo->route());
        QVERIFY(read);
        QCOMPARE(read->route.settings.checkAerodromeNfz, true);  // the demo route's flags
        QCOMPARE(read->route.settings.checkCustomNfz, false);
        mission::Route route = read->route;
        route.settings.checkAerodromeNfz = false;
        route.settings.checkCustomNfz = true;
        auto saved = answer<pb::CreateOrUpdateObjectResponse>(admin.client.createOrUpdate(mission::routeToHci(route)));
        QVERIFY2(saved->isOk(), qPrintable(saved->error().toString()));
        auto got = answer<pb::GetObjectResponse>(admin.client.getObject(hci::HciObjectType::Route, demoId));
        QVERIFY(got->isOk());
        const pb::Route &stored = got->response<pb::GetObjectResponse>().object().route();
        QCOMPARE(stored.checkaerodromenfz(), false);
        QCOMPARE(stored.checkcustomnfz(), true);
        auto back = mission::routeFromHci(stored);
        QVERIFY(back);
        QCOMPARE(back->route.settings.checkAerodromeNfz, false);
        QCOMPARE(back->route.settings.checkCustomNfz, true);
    }
};

QTEST_GUILESS_MAIN(TestServerZones)
#include "tst_serverzones.moc"
