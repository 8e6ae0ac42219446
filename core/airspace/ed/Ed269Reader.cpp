// EUROCAE ED-269: a JSON object with `features`, each a zone whose `geometry` is a list of
// volumes (uomDimensions, lower and upper limits with their references, a horizontal projection
// that is a Circle or a Polygon).
#include "EdReading.h"

// i18n: not text below (file diagnostics naming ED-269 fields and JSON paths)
namespace sortie::airspace::ed {

using namespace reading;
using mission::formats::JsonPathError;

namespace ed269 {

Volume volume(const JsonCursor &c, GeoidAccess &geoid)
{
    c.requireObject();
    Volume v;
    const JsonCursor projection = c.at("horizontalProjection");
    projection.requireObject();
    const QString uom = single(c.at("uomDimensions")).string();
    const QString type = single(projection.at("type")).string();
    if (type.compare(QLatin1String("Circle"), Qt::CaseInsensitive) == 0) {
        const GeoPoint center = position(projection.at("center"));
        const JsonCursor radius = single(projection.at("radius"));
        double r = radius.number();
        if (uom.trimmed().toUpper() == QLatin1String("FT"))
            r *= 0.3048;
        if (!(r > 0))
            radius.fail(QStringLiteral("the radius must be positive"));
        v.circle = Circle{center, r};
    } else if (type.compare(QLatin1String("Polygon"), Qt::CaseInsensitive) == 0) {
        const JsonCursor coordinates = projection.at("coordinates");
        // Rings of positions; one ring written without its list is read as the outer ring.
        if (coordinates.arraySize() > 0 && coordinates.at(size_t(0)).arraySize() > 0 && coordinates.at(size_t(0)).at(size_t(0)).value().is_number()) {
            const Json wrapped = Json::array({coordinates.value()});
            v.polygons.push_back(polygon(JsonCursor(wrapped, coordinates.path())));
        } else {
            v.polygons.push_back(polygon(coordinates));
        }
    } else {
        projection.at("type").fail(QStringLiteral("horizontal projection \"%1\" is neither Circle nor Polygon").arg(type));
    }
    const GeoPoint where = anchor(v);
    const auto lowerRef = c.find("lowerVerticalReference"), upperRef = c.find("upperVerticalReference");
    const auto lower = c.find("lowerLimit"), upper = c.find("upperLimit");
    if (lower && !lower->isNull()) {
        if (!lowerRef)
            c.fail(QStringLiteral("a lowerLimit needs its lowerVerticalReference"));
        v.lower = limit(*lower, uom, *lowerRef, false, where, geoid);
    }
    if (upper && !upper->isNull()) {
        if (!upperRef)
            c.fail(QStringLiteral("an upperLimit needs its upperVerticalReference"));
        v.upper = limit(*upper, uom, *upperRef, true, where, geoid);
    }
    checkLimits(c, v);
    return v;
}

GeoZone zone(const JsonCursor &f, GeoidAccess &geoid)
{
    f.requireObject();
    GeoZone z;
    z.format = Format::Ed269;
    z.identifier = text(single(f.at("identifier")));
    if (z.identifier.trimmed().isEmpty())
        f.failAt("identifier", QStringLiteral("the zone has no identifier"));
    z.country = textOr(f, "country");
    z.name = textOr(f, "name");
    if (z.name.isEmpty())
        z.name = z.identifier;
    const JsonCursor restriction = single(f.at("restriction"));
    const std::optional<Restriction> r = restrictionFromName(restriction.string().trimmed().toUpper());
    if (!r)
        restriction.fail(QStringLiteral("restriction \"%1\" is not PROHIBITED, REQ_AUTHORISATION, CONDITIONAL or NO_RESTRICTION")
                             .arg(restriction.string()));
    z.restriction = *r;
    z.restrictionConditions = strings(f, "restrictionConditions");
    z.reasons = strings(f, "reason");
    z.otherReasonInfo = textOr(f, "otherReasonInfo");
    z.message = textOr(f, "message");
    z.uSpaceClasses = strings(f, "uSpaceClass");
    if (const auto applicability = f.find("applicability"); applicability && !applicability->isNull())
        for (size_t i = 0; i < applicability->arraySize(); ++i)
            z.applicability.push_back(period(applicability->at(i)));
    if (const auto authorities = f.find("zoneAuthority"); authorities && !authorities->isNull()) {
        if (authorities->value().is_object())
            z.authorities.push_back(authority(*authorities));
        else
            for (size_t i = 0; i < authorities->arraySize(); ++i)
                z.authorities.push_back(authority(authorities->at(i)));
    }
    const JsonCursor geometry = f.at("geometry");
    if (geometry.value().is_object()) {
        z.volumes.push_back(volume(geometry, geoid));
    } else {
        for (size_t i = 0; i < geometry.arraySize(); ++i)
            z.volumes.push_back(volume(geometry.at(i), geoid));
    }
    if (z.volumes.empty())
        geometry.fail(QStringLiteral("the zone has no volume"));
    return z;
}

} // namespace ed269

// The top level's check, shared with detection: an object whose features are ED-269 zones.
bool looksLikeEd269(const Json &root)
{
    if (!root.is_object() || root.contains("type") || !root.contains("features") || !root["features"].is_array())
        return false;
    for (const Json &f : root["features"])
        if (f.is_object() && (f.contains("restriction") || (f.contains("geometry") && f["geometry"].is_array())))
            return true;
    return root["features"].empty();
}

mission::Result<GeoZoneFile> readEd269Json(const Json &root, const ReadOptions &options)
{
    GeoZoneFile out;
    out.format = Format::Ed269;
    GeoidAccess geoid(options.geoidGrid);
    try {
        const JsonCursor top(root);
        top.requireObject();
        if (top.find("type"))
            top.at("type").fail(QStringLiteral("an ED-269 file is a plain JSON object, not GeoJSON (a \"type\" at the top)"));
        const JsonCursor features = top.at("features");
        for (size_t i = 0; i < features.arraySize(); ++i) {
            try {
                out.zones.push_back(ed269::zone(features.at(i), geoid));
            } catch (const JsonPathError &e) {
                out.problems << leftOut(featureLabel(features.at(i).value(), i), e);
            }
        }
    } catch (const JsonPathError &e) {
        return mission::formats::errorAt(e);
    }
    return out;
}

mission::Result<GeoZoneFile> readEd269(const QByteArray &data, const ReadOptions &options)
{
    const mission::Result<Json> parsed = mission::formats::parseJson(data);
    if (!parsed)
        return parsed.error();
    return readEd269Json(parsed.value(), options);
}

} // namespace sortie::airspace::ed
