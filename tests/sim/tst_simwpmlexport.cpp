// The UgCS SDK's ExportRouteToWpml sample, step by step over loopback against the simulator: find the
// "DJI Matrice 350 RTK" profile, build an unsaved one-waypoint route for it, process it, and export it
// with W_RELATIVE_TO_FIRST_WP. The answer is a KMZ holding both WPML documents, which parse as XML and
// read back through Sortie's importer. A route for a non-DJI profile is refused with its reason.
#include "HciClient.h"
#include "../hci/HciTestSupport.h"
#include "Messages.pb.h"
#include "WpmlFormat.h"
#include "ZipArchive.h"

#include <QXmlStreamReader>
#include <QtTest>

using namespace sortie;
using hci::HciClient;
using hci::HciError;
using hci::HciObjectType;
using hci::HciSession;
namespace pb = com::ugcs::ucs::proto;

namespace {

constexpr double kRad = 3.14159265358979323846 / 180.0;

template<class T>
T call(hci::HciReply *raw, HciError *error = nullptr)
{
    auto reply = test::keep(raw);
    if (!test::finishes(reply.get()))
        qFatal("no answer to %s", qPrintable(reply->requestName()));
    if (error)
        *error = reply->error();
    return reply->response<T>();
}

// The sample's route: no mission, no id, corner radius 15, one waypoint at 30 m AGL.
pb::Route sampleRoute(const pb::VehicleProfile &profile)
{
    pb::Route r;
    r.set_name("WPML export sample");
    r.set_checkaerodromenfz(false);
    r.set_checkcustomnfz(false);
    r.set_initialspeed(5);
    r.set_maxspeed(10);
    r.set_maxaltitude(10000);
    r.set_safealtitude(20);
    r.set_cornerradius(15);
    *r.mutable_vehicleprofile() = profile;
    auto *s = r.add_segments();
    s->set_algorithmclassname("com.ugcs.ucs.service.routing.impl.WaypointAlgorithm");
    s->mutable_figure()->set_type(pb::FT_POINT);
    auto *p = s->mutable_figure()->add_points();
    p->set_latitude(46.7740639 * kRad);
    p->set_longitude(8.3350036 * kRad);
    p->set_aglaltitude(30);
    p->set_altitudetype(pb::AT_AGL);
    for (const auto &[name, value] : {std::pair{"speed", "5.0"}, {"wpTurnType", "STOP_AND_TURN"}, {"avoidObstacles", "true"},
                                      {"avoidTerrain", "true"}, {"altitudeType", "AGL"}, {"cornerRadius", ""}}) {
        auto *v = s->add_parametervalues();
        v->set_name(name);
        v->set_value(value);
    }
    return r;
}

bool wellFormed(const QByteArray &xml)
{
    QXmlStreamReader x(xml);
    while (!x.atEnd())
        x.readNext();
    return !x.hasError();
}

} // namespace

class TestSimWpmlExport : public QObject
{
    Q_OBJECT

private slots:
    void theSdkSampleGetsAKmz()
    {
        test::SimServer sim;
        HciSession session;
        HciClient client(&session);
        session.open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(test::reaches(session, HciSession::State::Ready));

        // GetObjectList("VehicleProfile"), the one named "DJI Matrice 350 RTK" (case-insensitive).
        const auto profiles = call<pb::GetObjectListResponse>(client.listObjects(HciObjectType::VehicleProfile));
        pb::VehicleProfile m350, mavic;
        for (const auto &w : profiles.objects()) {
            const QString name = QString::fromStdString(w.vehicleprofile().name());
            if (name.compare(QLatin1String("dji matrice 350 rtk"), Qt::CaseInsensitive) == 0)
                m350 = w.vehicleprofile();
            if (name == QLatin1String("DJI Mavic 3 Enterprise"))
                mavic = w.vehicleprofile();
        }
        QVERIFY(m350.has_id());
        QVERIFY(mavic.has_id());
        QVERIFY(m350.parameters_size() > 0);

        HciError error;
        const auto processed = call<pb::ProcessRouteResponse>(client.processRoute(sampleRoute(m350)), &error);
        QVERIFY2(!error.isError(), qPrintable(error.toString()));

        pb::ExportRouteToWpmlRequest request;
        request.set_clientid(session.clientId());
        *request.mutable_route() = processed.processedroute();
        request.set_altitudemode(pb::W_RELATIVE_TO_FIRST_WP);
        const auto exported = call<pb::ExportRouteToWpmlResponse>(session.send(request), &error);
        QVERIFY2(!error.isError(), qPrintable(error.toString()));
        const QByteArray kmz = QByteArray::fromStdString(exported.routedata());
        QVERIFY(kmz.startsWith("PK"));

        const auto entries = mission::formats::readZip(kmz);
        QVERIFY(entries.ok());
        QCOMPARE(int(entries->size()), 2);
        for (const auto &e : *entries)
            QVERIFY2(wellFormed(e.data), qPrintable(e.path));
        const QByteArray waylines = entries->at(1).data;
        QVERIFY(waylines.contains("<wpml:droneEnumValue>89</wpml:droneEnumValue>"));
        QVERIFY(waylines.contains("<wpml:executeHeightMode>relativeToStartPoint</wpml:executeHeightMode>"));

        const auto imported = mission::formats::readWpml(kmz);
        QVERIFY2(imported.ok(), imported.ok() ? "" : qPrintable(imported.error().toString()));
        const auto &route = imported->routes.front();
        // The climb over the take-off spot (the first waypoint's ground), then the waypoint 30 m up.
        QCOMPARE(int(route.segments.size()), 2);
        const auto &climb = std::get<mission::Waypoint>(route.segments[0]);
        const auto &target = std::get<mission::Waypoint>(route.segments[1]);
        // The take-off point (wpml:takeOffRefPoint, the first waypoint's ground) comes back as the
        // route's home, so the heights above it come back as AMSL: take-off + 20 m and + 30 m.
        QVERIFY(route.settings.home);
        const double takeoff = route.settings.home->altitudeAmsl;
        QCOMPARE(climb.altitudeType, mission::AltitudeType::Amsl);
        QVERIFY2(std::abs(climb.altitude - (takeoff + 20.0)) < 1e-9, qPrintable(QString::number(climb.altitude)));
        QVERIFY2(std::abs(target.altitude - (takeoff + 30.0)) < 1e-9, qPrintable(QString::number(target.altitude)));
        QVERIFY(std::abs(target.position.latitude - 46.7740639) < 1e-9);
        QVERIFY(std::abs(target.position.longitude - 8.3350036) < 1e-9);
        QCOMPARE(imported->droneName, QStringLiteral("DJI Matrice 350 RTK"));
    }

    void aNonDjiProfileIsRefusedWithItsReason()
    {
        test::SimServer sim;
        HciSession session;
        HciClient client(&session);
        session.open(QStringLiteral("127.0.0.1"), sim.port(), QStringLiteral("admin"), QStringLiteral("admin"));
        QVERIFY(test::reaches(session, HciSession::State::Ready));
        const auto profiles = call<pb::GetObjectListResponse>(client.listObjects(HciObjectType::VehicleProfile));
        pb::VehicleProfile emu;
        for (const auto &w : profiles.objects())
            if (w.vehicleprofile().name() == "EMU Copter")
                emu = w.vehicleprofile();
        QVERIFY(emu.has_id());
        const auto processed = call<pb::ProcessRouteResponse>(client.processRoute(sampleRoute(emu)));
        pb::ExportRouteToWpmlRequest request;
        request.set_clientid(session.clientId());
        *request.mutable_route() = processed.processedroute();
        request.set_altitudemode(pb::W_RELATIVE_TO_FIRST_WP);
        HciError error;
        call<pb::ExportRouteToWpmlResponse>(session.send(request), &error);
        QVERIFY(error.isError());
        QVERIFY2(error.toString().contains(QStringLiteral("\"EMU Copter\" is not one")), qPrintable(error.toString()));
    }
};

QTEST_GUILESS_MAIN(TestSimWpmlExport)
#include "tst_simwpmlexport.moc"
