// UAS geographical zones (core/airspace/ed): ED-269 files written here from the format's field list
// (circles, polygons, three stacked volumes, AGL / AMSL / WGS84 limits in metres and feet, 99999,
// one-element lists, repeated vertices, schedules across midnight and at weekends, expired and
// future zones, every restriction), the ED-318 samples (tests/data/samples/geozones), bad features
// named and left out, detection by content beside the other zone files, and when a zone applies.
#include "Egm96Geoid.h"
#include "TestData.h"
#include "GeoZoneReader.h"
#include "ZoneFiles.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace sortie::airspace;
using namespace sortie::airspace::ed;

namespace {
// tests/data/geozones: ed269-written.json, written from ED-269's field list (fourteen zones, the
// last six bad); ed318-written.json, from ED-318's: a MultiPolygon in feet, U-space airspace, a
// sunrise schedule (not supported: left out) and a LineString (no volume: left out).
QByteArray dataFile(const char *name)
{
    QFile f((QString::fromUtf8(sortieTestData()) + QStringLiteral("/")) + QLatin1String(name));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QDateTime utc(const char *iso)
{
    return QDateTime::fromString(QString::fromLatin1(iso), Qt::ISODate).toUTC();
}

TimeWindow at(const char *from, const char *to)
{
    return {utc(from), utc(to)};
}

const GeoZone *byId(const GeoZoneFile &f, const char *id)
{
    for (const GeoZone &z : f.zones)
        if (z.identifier == QLatin1String(id))
            return &z;
    return nullptr;
}

QByteArray sample(const char *name)
{
    QFile f((QString::fromUtf8(sortieTestData()) + QStringLiteral("/samples/geozones/")) + QLatin1String(name));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
} // namespace

class TstGeoZones : public QObject
{
    Q_OBJECT
    QByteArray kEd269, kEd318;

private slots:
    void initTestCase()
    {
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedKingdom));
        kEd269 = dataFile("geozones/ed269-written.json");
        kEd318 = dataFile("geozones/ed318-written.json");
        QVERIFY(!kEd269.isEmpty() && !kEd318.isEmpty());
    }

    void ed269ReadsWhatTheFormatSays()
    {
        const auto read = readEd269(kEd269);
        QVERIFY2(read.ok(), read.ok() ? "" : qPrintable(read.error().toString()));
        QCOMPARE(read->format, Format::Ed269);
        QCOMPARE(read->zones.size(), size_t(9));  // 8 good, and the bow tie (its shape is core/airspace's to refuse)

        const GeoZone *house = byId(*read, "CHP001");
        QVERIFY(house);
        QCOMPARE(house->name, QStringLiteral("Bundeshaus"));
        QCOMPARE(house->country, QStringLiteral("CHE"));
        QCOMPARE(house->restriction, Restriction::Prohibited);
        QCOMPARE(house->reasons, QStringList{QStringLiteral("SENSITIVE")});
        QCOMPARE(house->otherReasonInfo, QStringLiteral("Federal buildings"));
        QCOMPARE(house->volumes.size(), size_t(1));
        const Volume &circle = house->volumes[0];
        QVERIFY(circle.circle && circle.polygons.empty());
        QCOMPARE(circle.circle->center, (GeoPoint{46.9466, 7.4440}));  // [longitude, latitude]
        QCOMPARE(circle.circle->radius, 300.0);
        QVERIFY(!circle.lower);  // 0 AGL: the ground
        QVERIFY(!circle.upper);  // 99999: unlimited
        QCOMPARE(house->authorities.size(), size_t(1));
        QCOMPARE(house->authorities[0].email, QStringLiteral("drones@fedpol.example"));
        QVERIFY(house->applicability.size() == 1 && house->applicability[0].permanent);

        // Three stacked volumes, metres and feet, AGL and AMSL, a one-element list for a value,
        // repeated and closing vertices dropped.
        const GeoZone *ctr = byId(*read, "CHA002");
        QVERIFY(ctr);
        QCOMPARE(ctr->restriction, Restriction::ReqAuthorisation);
        QCOMPARE(ctr->message, QStringLiteral("Ask Skyguide before you fly"));
        QCOMPARE(ctr->volumes.size(), size_t(3));
        QCOMPARE(ctr->volumes[0].polygons.at(0).rings.at(0).size(), size_t(4));
        QCOMPARE(ctr->volumes[0].upper, (VerticalLimit{150, VerticalReference::Agl}));
        QVERIFY(std::abs(ctr->volumes[1].lower->metres - 492 * 0.3048) < 1e-9);
        QCOMPARE(ctr->volumes[1].lower->reference, VerticalReference::Agl);
        QVERIFY(std::abs(ctr->volumes[1].upper->metres - 914.4) < 1e-9);
        QCOMPARE(ctr->volumes[1].upper->reference, VerticalReference::Amsl);
        QCOMPARE(ctr->volumes[1].polygons.at(0).rings.at(0).size(), size_t(4));  // an open ring stays as it is
        QCOMPARE(ctr->volumes[2].lower, (VerticalLimit{914, VerticalReference::Amsl}));
        QVERIFY(!ctr->volumes[2].upper);
        const Authority &skyguide = ctr->authorities.at(0);
        QCOMPARE(skyguide.purpose, QStringLiteral("AUTHORIZATION"));
        QCOMPARE(skyguide.intervalBefore, QStringLiteral("P3D"));
        QCOMPARE(contactText(skyguide), QStringLiteral("Skyguide (UAS desk), +41 00 000 00 00, https://skyguide.example, ask P3D before"));

        const GeoZone *aare = byId(*read, "CHC003");
        QCOMPARE(aare->uSpaceClasses, QStringList{QStringLiteral("EUROCONTROL")});
        QCOMPARE(aare->applicability.at(0).schedule.at(0).days, std::uint8_t(0x60));  // Saturday, Sunday
        QCOMPARE(aare->applicability.at(0).schedule.at(0).start, 18 * 3600);
        QCOMPARE(aare->applicability.at(0).schedule.at(0).end, 23 * 3600);
        QCOMPARE(applicabilityText(aare->applicability, QTimeZone::utc()),
                 QStringLiteral("2026-05-01 00:00 to 2026-09-30 23:59, Sat Sun 18:00–23:00"));
        QCOMPARE(byId(*read, "CHN007")->restriction, Restriction::NoRestriction);
        QCOMPARE(byId(*read, "CHN007")->uSpaceClasses, (QStringList{QStringLiteral("EUROCONTROL"), QStringLiteral("CORUS")}));

        // WGS-84 (ellipsoidal) through the EGM96 geoid where the volume is: H = h - N.
        QString error;
        const auto geoid = sortie::datum::Egm96Geoid::open(sortie::datum::Egm96Geoid::defaultGridPath(), &error);
        QVERIFY2(geoid, qPrintable(error));
        const std::optional<double> n = geoid->undulation(46.97, 7.43);
        QVERIFY(n && *n > 40 && *n < 60);
        const GeoZone *ellipsoid = byId(*read, "CHW008");
        QVERIFY(ellipsoid);
        QCOMPARE(ellipsoid->volumes[0].upper->reference, VerticalReference::Amsl);
        QVERIFY2(std::abs(ellipsoid->volumes[0].upper->metres - (600 - *n)) < 0.01, qPrintable(QString::number(ellipsoid->volumes[0].upper->metres)));
    }

    // Each bad feature is named (place, name, identifier, JSON path) with its reason; the rest load.
    void ed269NamesEveryFeatureItLeavesOut()
    {
        const auto read = readEd269(kEd269);
        QVERIFY(read.ok());
        const QStringList &p = read->problems;
        QCOMPARE(p.size(), 5);
        QVERIFY2(p[0].startsWith(QStringLiteral("feature 9 ('Forbidden spelling', BAD009) (at /features/8/restriction)")) && p[0].contains(QStringLiteral("FORBIDDEN")), qPrintable(p[0]));
        QVERIFY2(p[1].contains(QStringLiteral("BAD010")) && p[1].contains(QStringLiteral("at least 3 distinct positions, found 2")), qPrintable(p[1]));
        QVERIFY2(p[2].contains(QStringLiteral("BAD011")) && p[2].contains(QStringLiteral("/schedule/0/startTime")) && p[2].contains(QStringLiteral("25:00Z")), qPrintable(p[2]));
        QVERIFY2(p[3].contains(QStringLiteral("BAD012")) && p[3].contains(QStringLiteral("\"no limit\"")), qPrintable(p[3]));
        QVERIFY2(p[4].contains(QStringLiteral("BAD013")) && p[4].contains(QStringLiteral("QNH")), qPrintable(p[4]));

        // As zones: one per volume, each knowing its zone and place; the bow tie left out whole.
        const ZoneFile zones = zonesOfGeoZones(read.value(), QStringLiteral("ch.json"));
        QCOMPARE(zones.zones.size(), size_t(10));
        QCOMPARE(zones.problems.size(), 6);
        QVERIFY2(zones.problems.last().contains(QStringLiteral("ED-269 zone BAD014 ('Bow tie') was left out: volume 1")), qPrintable(zones.problems.last()));
        const Zone &second = zones.zones[2];
        QCOMPARE(second.geoZone->identifier, QStringLiteral("CHA002"));
        QCOMPARE(second.volume, 2);
        QCOMPARE(second.name, QStringLiteral("Belp CTR"));
        QCOMPARE(second.origin, QStringLiteral("ch.json, CHA002"));
        QCOMPARE(second.floor->reference, HeightReference::AboveTerrain);
        QCOMPARE(second.ceiling->reference, HeightReference::Amsl);
        QVERIFY(second.geoZone == zones.zones[1].geoZone);  // shared, not copied per volume
    }

    void whenAZoneApplies()
    {
        const auto read = readEd269(kEd269);
        QVERIFY(read.ok());
        const GeoZone &aare = *byId(*read, "CHC003"), &market = *byId(*read, "CHC004");
        // Weekend evenings, May to September.
        QVERIFY(aare.appliesDuring(at("2026-06-06T18:30:00Z", "2026-06-06T19:00:00Z")));   // Saturday
        QVERIFY(!aare.appliesDuring(at("2026-06-08T18:30:00Z", "2026-06-08T19:00:00Z")));  // Monday
        QVERIFY(!aare.appliesDuring(at("2026-06-06T17:00:00Z", "2026-06-06T17:59:00Z")));  // before the evening
        QVERIFY(aare.appliesDuring(at("2026-06-06T17:30:00Z", "2026-06-06T18:10:00Z")));   // a flight into it
        QVERIFY(!aare.appliesDuring(at("2025-06-07T18:30:00Z", "2025-06-07T19:00:00Z")));  // a Saturday before its dates
        QVERIFY(!aare.appliesDuring(at("2026-10-03T18:30:00Z", "2026-10-03T19:00:00Z")));  // and after
        QVERIFY(aare.appliesDuring(at("2026-06-01T00:00:00Z", "2026-06-30T00:00:00Z")));   // a month holds weekends
        // Friday 22:00 to 02:00: into Saturday morning.
        QVERIFY(market.appliesDuring(at("2026-06-05T23:30:00Z", "2026-06-05T23:40:00Z")));
        QVERIFY(market.appliesDuring(at("2026-06-06T01:30:00Z", "2026-06-06T01:40:00Z")));
        QVERIFY(!market.appliesDuring(at("2026-06-06T03:00:00Z", "2026-06-06T03:10:00Z")));
        QVERIFY(!market.appliesDuring(at("2026-06-04T23:30:00Z", "2026-06-04T23:40:00Z")));  // Thursday night
        // Expired, future, permanent.
        const TimeWindow now = at("2026-12-02T06:00:00Z", "2026-12-02T06:30:00Z");
        QVERIFY(!byId(*read, "CHX005")->appliesDuring(now));
        QVERIFY(!byId(*read, "CHF006")->appliesDuring(now));
        QVERIFY(byId(*read, "CHF006")->appliesDuring(at("2030-01-02T10:00:00Z", "2030-01-02T10:30:00Z")));
        QVERIFY(byId(*read, "CHP001")->appliesDuring(now));

        // A clock with an offset is the same moment in UTC: 20:00+02:00 is 18:00Z (and the weekday
        // is the file's).
        const QByteArray offset = R"({"features": [{"identifier": "O1", "restriction": "PROHIBITED", "zoneAuthority": [],
          "applicability": [{"permanent": "NO", "schedule": [{"day": ["SAT"], "startTime": "01:00+02:00", "endTime": "03:00+02:00"}]}],
          "geometry": [{"uomDimensions": "M", "lowerLimit": 0, "lowerVerticalReference": "AGL", "upperLimit": 50, "upperVerticalReference": "AGL",
                        "horizontalProjection": {"type": "Circle", "center": [7.4, 46.9], "radius": 100}}]}]})";
        const auto o = readEd269(offset);
        QVERIFY2(o.ok() && o->problems.isEmpty(), o.ok() ? qPrintable(o->problems.join('\n')) : "");
        const GeoZone &early = o->zones.at(0);
        QVERIFY(early.appliesDuring(at("2026-06-05T23:30:00Z", "2026-06-05T23:40:00Z")));  // Friday 23:30Z is Saturday 01:30+02
        QVERIFY(!early.appliesDuring(at("2026-06-06T23:30:00Z", "2026-06-06T23:40:00Z")));
    }

    void ed318SamplesRead()
    {
        const QByteArray layers = sample("ed318-two-layers.json");
        QVERIFY(!layers.isEmpty());
        QCOMPARE(detectGeoZoneFormat(layers), std::optional<Format>(Format::Ed318));
        const auto read = readEd318(layers);
        QVERIFY2(read.ok(), read.ok() ? "" : qPrintable(read.error().toString()));
        QVERIFY2(read->problems.isEmpty(), qPrintable(read->problems.join('\n')));
        QCOMPARE(read->zones.size(), size_t(1));
        const GeoZone &z = read->zones[0];
        QCOMPARE(z.format, Format::Ed318);
        QCOMPARE(z.identifier, QStringLiteral("NFZ6547"));
        QCOMPARE(z.name, QStringLiteral("LFPG-2"));
        QCOMPARE(z.restriction, Restriction::ReqAuthorisation);  // REQ_AUTHORIZATION
        QCOMPARE(z.otherReasonInfo, QStringLiteral("Flying Whales - part 2"));  // the English of two
        QCOMPARE(z.volumes.size(), size_t(2));
        QCOMPARE(z.volumes[0].lower, (VerticalLimit{50, VerticalReference::Agl}));
        QCOMPARE(z.volumes[0].upper, (VerticalLimit{150, VerticalReference::Agl}));
        QVERIFY(!z.volumes[1].lower);
        QCOMPARE(z.volumes[1].polygons.at(0).rings.at(0).size(), size_t(3));
        QCOMPARE(z.authorities.at(0).name, QStringLiteral("LFPG-UASZoneManager"));
        QCOMPARE(z.authorities.at(0).email, QStringLiteral("UASZoneManager@lfpg.fr"));
        QCOMPARE(read->issued, std::optional<QDateTime>(utc("2018-12-01T15:59:59Z")));
        // "ANY" day 16:00-17:00 and Sundays 10:00-12:00, during 2019.
        QVERIFY(z.appliesDuring(at("2019-06-02T11:00:00Z", "2019-06-02T11:10:00Z")));   // Sunday
        QVERIFY(!z.appliesDuring(at("2019-06-03T11:00:00Z", "2019-06-03T11:10:00Z")));  // Monday morning
        QVERIFY(z.appliesDuring(at("2019-06-03T16:30:00Z", "2019-06-03T16:40:00Z")));   // any afternoon
        QVERIFY(!z.appliesDuring(at("2020-06-07T11:00:00Z", "2020-06-07T11:10:00Z")));  // after its end

        const auto circle = readEd318(sample("ed318-circle.json"));
        QVERIFY(circle.ok() && circle->problems.isEmpty());
        const GeoZone &c = circle->zones.at(0);
        QCOMPARE(c.restriction, Restriction::Prohibited);
        QCOMPARE(c.volumes.at(0).circle->radius, 3500.0);
        QCOMPARE(c.volumes.at(0).circle->center, (GeoPoint{50.122901, 2.636866}));
        QVERIFY(c.applicability.empty());
        QVERIFY(c.appliesDuring(at("2026-12-02T06:00:00Z", "2026-12-02T07:00:00Z")));  // no limited applicability: always
    }

    void ed318WrittenFile()
    {
        const auto read = readEd318(kEd318);
        QVERIFY(read.ok());
        QCOMPARE(read->zones.size(), size_t(1));
        const GeoZone &harbour = read->zones[0];
        QCOMPARE(harbour.name, QStringLiteral("Harbour (en)"));
        QCOMPARE(harbour.restriction, Restriction::ReqAuthorisation);  // U-space airspace: a flight authorisation
        QCOMPARE(harbour.volumes.at(0).polygons.size(), size_t(2));
        QVERIFY(std::abs(harbour.volumes[0].upper->metres - 400 * 0.3048) < 1e-9);
        QCOMPARE(harbour.authorities.at(0).email, QStringLiteral("uspace@iaa.example"));
        QCOMPARE(read->problems.size(), 2);
        QVERIFY2(read->problems[0].contains(QStringLiteral("IEB002")) && read->problems[0].contains(QStringLiteral("sunrise or sunset")), qPrintable(read->problems[0]));
        QVERIFY2(read->problems[1].contains(QStringLiteral("IEL003")) && read->problems[1].contains(QStringLiteral("LineString")), qPrintable(read->problems[1]));
    }

    // Found by content beside the other zone files: an ED-269 .json, an ED-318 .geojson, and a
    // Sortie GeoJSON that is neither.
    void detectedByContent()
    {
        QTemporaryDir dir;
        const auto write = [&](const char *name, const QByteArray &data) {
            QFile f(dir.filePath(QLatin1String(name)));
            return f.open(QIODevice::WriteOnly) && f.write(data) == data.size() ? f.fileName() : QString();
        };
        const auto ed269 = loadZoneFile(write("ch.json", kEd269));
        QVERIFY2(ed269.ok(), ed269.ok() ? "" : qPrintable(ed269.error().toString()));
        QCOMPARE(ed269->zones.size(), size_t(10));
        QVERIFY(ed269->zones[0].geoZone);
        const auto ed318 = loadZoneFile(write("fr.geojson", sample("ed318-two-layers.json")));
        QVERIFY(ed318.ok());
        QCOMPARE(ed318->zones.size(), size_t(2));
        QCOMPARE(ed318->zones[1].volume, 2);
        const QByteArray plain = R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"name": "Mast", "radius": 50},
                                     "geometry": {"type": "Point", "coordinates": [24.1, 56.9]}}]})";
        QVERIFY(!detectGeoZoneFormat(plain));
        const auto geojson = loadZoneFile(write("plain.json", plain));
        QVERIFY(geojson.ok());
        QCOMPARE(geojson->zones.size(), size_t(1));
        QVERIFY(!geojson->zones[0].geoZone);
        // Not JSON at all: the reader's error, with the line.
        const auto broken = readEd269("{\"features\": [\n{]");
        QVERIFY(!broken.ok());
        QCOMPARE(broken.error().line, 2);
    }
};

QTEST_GUILESS_MAIN(TstGeoZones)
#include "tst_geozones.moc"
