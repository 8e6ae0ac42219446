// NfzConversion: the server's NoFlightZone (radians, metres, Prism / ConeFrustum, AT_WGS84 /
// AT_AGL) as zones and custom zones back; zones that cannot be converted are left out, named.
#include "Domain.pb.h"
#include "NfzConversion.h"

#include <QtTest>

#include <numbers>

using namespace sortie::airspace;
namespace pb = com::ugcs::ucs::proto;

namespace {
constexpr double kRad = std::numbers::pi / 180.0;

pb::NoFlightZone prism(int id, const char *name, pb::NfzType type, std::vector<std::pair<double, double>> corners)
{
    pb::NoFlightZone z;
    z.set_id(id);
    z.set_version(3);
    z.set_name(name);
    z.set_type(type);
    z.set_tag("keep-me");
    for (const auto &[lat, lon] : corners) {
        auto *p = z.mutable_prism()->add_points();
        p->set_latitude(lat * kRad);
        p->set_longitude(lon * kRad);
    }
    return z;
}

const std::vector<std::pair<double, double>> kSquare{{56.98, 24.06}, {56.98, 24.09}, {56.99, 24.09}, {56.99, 24.06}};
} // namespace

class TestNfzConversion : public QObject
{
    Q_OBJECT

private slots:
    void prismInRadiansWithHeights()
    {
        pb::NoFlightZone z = prism(12, "Spilve", pb::NT_AERODROME, kSquare);
        z.mutable_prism()->set_altitudetype(pb::AT_WGS84);
        z.mutable_prism()->set_basealtitude(40);
        z.mutable_prism()->set_height(110);
        QString why;
        const auto zone = NfzConversion::toZone(z, &why);
        QVERIFY2(zone, qPrintable(why));
        QCOMPARE(zone->name, QStringLiteral("Spilve"));
        QCOMPARE(zone->kind, ZoneKind::Exclusion);
        QCOMPARE(zone->source, ZoneSource::ServerAerodrome);
        QCOMPARE(zone->serverId, std::optional<int>(12));
        QCOMPARE(zone->serverVersion, 3);
        const auto &ring = std::get<ZonePolygons>(zone->shape).parts.at(0).rings.at(0);
        QCOMPARE(ring.size(), size_t(4));
        QVERIFY(qAbs(ring[2].latitude - 56.99) < 1e-12 && qAbs(ring[2].longitude - 24.09) < 1e-12);
        QCOMPARE(zone->floor, std::optional(HeightLimit{40, HeightReference::Amsl}));
        QCOMPARE(zone->ceiling, std::optional(HeightLimit{150, HeightReference::Amsl}));  // base + height
    }

    void prismFromTheGroundAndUnlimited()
    {
        pb::NoFlightZone z = prism(5, "Works", pb::NT_CUSTOM, kSquare);
        z.mutable_prism()->add_points()->CopyFrom(z.prism().points(0));  // closed ring: read open
        z.mutable_prism()->set_altitudetype(pb::AT_AGL);
        z.mutable_prism()->set_basealtitude(0);
        QString why;
        const auto zone = NfzConversion::toZone(z, &why);
        QVERIFY2(zone, qPrintable(why));
        QCOMPARE(zone->source, ZoneSource::ServerCustom);
        QCOMPARE(std::get<ZonePolygons>(zone->shape).parts[0].rings[0].size(), size_t(4));
        QVERIFY(!zone->floor);    // 0 m AGL is the ground
        QVERIFY(!zone->ceiling);  // no height: unlimited
    }

    void coneFrustumAndCircle()
    {
        pb::NoFlightZone z;
        z.set_id(7);
        z.set_name("RIX CTR");
        z.set_type(pb::NT_AERODROME);
        auto *c = z.mutable_conefrustum();
        c->set_baselatitude(56.9236 * kRad);
        c->set_baselongitude(23.9711 * kRad);
        c->set_baseradius(5000);
        c->set_topradius(8000);
        c->set_altitudetype(pb::AT_WGS84);
        c->set_basealtitude(0);
        c->set_height(600);
        QString why;
        auto zone = NfzConversion::toZone(z, &why);
        QVERIFY2(zone, qPrintable(why));
        const auto &cone = std::get<ZoneConeFrustum>(zone->shape);
        QVERIFY(qAbs(cone.center.latitude - 56.9236) < 1e-12);
        QCOMPARE(cone.bottomRadius, 5000.0);
        QCOMPARE(cone.topRadius, 8000.0);
        QCOMPARE(zone->floor, std::optional(HeightLimit{0, HeightReference::Amsl}));
        QCOMPARE(zone->ceiling, std::optional(HeightLimit{600, HeightReference::Amsl}));

        c->set_topradius(5000);  // equal radii: a circle
        zone = NfzConversion::toZone(z, &why);
        QVERIFY2(zone, qPrintable(why));
        QCOMPARE(std::get<ZoneCircle>(zone->shape).radius, 5000.0);
    }

    void badZonesAreLeftOutNamed()
    {
        google::protobuf::RepeatedPtrField<pb::NoFlightZone> answer;
        *answer.Add() = prism(1, "Good", pb::NT_CUSTOM, kSquare);
        *answer.Add() = prism(2, "Two corners", pb::NT_CUSTOM, {{56.98, 24.06}, {56.99, 24.07}});
        pb::NoFlightZone empty;
        empty.set_id(3);
        *answer.Add() = empty;
        pb::NoFlightZone bad = prism(4, "Off the globe", pb::NT_CUSTOM, kSquare);
        bad.mutable_prism()->mutable_points(1)->set_latitude(2.0);  // radians: 114.6°
        *answer.Add() = bad;
        pb::NoFlightZone negative = prism(5, "Negative", pb::NT_CUSTOM, kSquare);
        negative.mutable_prism()->set_height(-10);
        *answer.Add() = negative;
        pb::NoFlightZone crossed = prism(6, "Bow tie", pb::NT_CUSTOM, {{56.98, 24.06}, {56.99, 24.09}, {56.98, 24.09}, {56.99, 24.06}});
        *answer.Add() = crossed;
        QStringList problems;
        const auto zones = NfzConversion::toZones(answer, &problems);
        QCOMPARE(zones.size(), size_t(1));
        QCOMPARE(zones[0].name, QStringLiteral("Good"));
        QCOMPARE(problems.size(), 5);
        QVERIFY2(problems[0].startsWith(QStringLiteral("NoFlightZone 2 ('Two corners') was left out: its prism has 2 corner(s)")),
                 qPrintable(problems[0]));
        QVERIFY2(problems[1].startsWith(QStringLiteral("NoFlightZone 3 was left out: it has no volume")), qPrintable(problems[1]));
        QVERIFY2(problems[2].contains(QStringLiteral("'Off the globe'")) && problems[2].contains(QStringLiteral("point 2")),
                 qPrintable(problems[2]));
        QVERIFY2(problems[3].contains(QStringLiteral("height -10 m")), qPrintable(problems[3]));
        QVERIFY2(problems[4].contains(QStringLiteral("'Bow tie'")) && problems[4].contains(QStringLiteral("cannot be checked")),
                 qPrintable(problems[4]));
    }

    void customZoneRoundTrip()
    {
        pb::NoFlightZone sent = prism(9, "Works", pb::NT_CUSTOM, kSquare);
        sent.mutable_prism()->set_altitudetype(pb::AT_AGL);
        sent.mutable_prism()->set_basealtitude(0);
        sent.mutable_prism()->set_height(60);
        QString why;
        Zone zone = *NfzConversion::toZone(sent, &why);
        zone.name = QStringLiteral("Works, extended");
        zone.ceiling = HeightLimit{80, HeightReference::AboveTerrain};
        const auto back = NfzConversion::toNfz(zone, &sent, &why);
        QVERIFY2(back, qPrintable(why));
        QCOMPARE(back->id(), 9);
        QCOMPARE(back->version(), 3);
        QCOMPARE(back->tag(), std::string("keep-me"));  // what Sortie does not model goes back as it came
        QCOMPARE(back->name(), std::string("Works, extended"));
        QCOMPARE(back->type(), pb::NT_CUSTOM);
        QCOMPARE(back->prism().altitudetype(), pb::AT_AGL);
        QCOMPARE(back->prism().basealtitude(), 0.0);
        QCOMPARE(back->prism().height(), 80.0);
        QCOMPARE(back->prism().points_size(), 4);
        QVERIFY(qAbs(back->prism().points(2).latitude() - 56.99 * kRad) < 1e-15);
        const auto again = NfzConversion::toZone(*back, &why);
        QVERIFY2(again, qPrintable(why));
        QCOMPARE(again->shape, zone.shape);
        QCOMPARE(again->ceiling, zone.ceiling);

        Zone circle;
        circle.name = QStringLiteral("Mast");
        circle.shape = ZoneCircle{{56.97, 24.08}, 120};
        circle.floor = HeightLimit{30, HeightReference::Amsl};
        circle.ceiling = HeightLimit{130, HeightReference::Amsl};
        const auto cone = NfzConversion::toNfz(circle, nullptr, &why);
        QVERIFY2(cone, qPrintable(why));
        QVERIFY(!cone->has_id());
        QCOMPARE(cone->conefrustum().baseradius(), 120.0);
        QCOMPARE(cone->conefrustum().topradius(), 120.0);
        QCOMPARE(cone->conefrustum().altitudetype(), pb::AT_WGS84);
        QCOMPARE(cone->conefrustum().basealtitude(), 30.0);
        QCOMPARE(cone->conefrustum().height(), 100.0);
        QCOMPARE(NfzConversion::toZone(*cone, &why)->shape, circle.shape);
    }

    void whatTheServerCannotHoldIsRefused_data()
    {
        QTest::addColumn<int>("variant");
        QTest::addColumn<QString>("reason");
        QTest::newRow("inclusion") << 0 << "inclusion zone";
        QTest::newRow("aerodrome") << 1 << "aerodrome zones";
        QTest::newRow("two references") << 2 << "different references";
        QTest::newRow("above home") << 3 << "above home";
        QTest::newRow("hole") << 4 << "without holes";
        QTest::newRow("ground to AMSL") << 5 << "AMSL ceiling";
    }
    void whatTheServerCannotHoldIsRefused()
    {
        QFETCH(int, variant);
        QFETCH(QString, reason);
        Zone z;
        z.name = QStringLiteral("Z");
        z.shape = ZonePolygons{{ZonePolygon{{{{56.98, 24.06}, {56.98, 24.09}, {56.99, 24.09}}}}}};
        switch (variant) {
        case 0: z.kind = ZoneKind::Inclusion; break;
        case 1: z.source = ZoneSource::ServerAerodrome; break;
        case 2: z.floor = HeightLimit{10, HeightReference::Amsl}, z.ceiling = HeightLimit{50, HeightReference::AboveTerrain}; break;
        case 3: z.ceiling = HeightLimit{50, HeightReference::AboveHome}; break;
        case 4: std::get<ZonePolygons>(z.shape).parts[0].rings.push_back({{56.985, 24.07}, {56.985, 24.08}, {56.986, 24.075}}); break;
        case 5: z.ceiling = HeightLimit{150, HeightReference::Amsl}; break;
        }
        QString why;
        QVERIFY(!NfzConversion::toNfz(z, nullptr, &why));
        QVERIFY2(why.contains(reason), qPrintable(why));
    }
};

QTEST_GUILESS_MAIN(TestNfzConversion)
#include "tst_nfzconversion.moc"
