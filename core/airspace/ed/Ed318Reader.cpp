// EUROCAE ED-318: a GeoJSON FeatureCollection with `metadata`; each feature's properties are the
// zone (texts per language, the restriction in `type`), each geometry carries its vertical `layer`;
// a circle is a Point with an `extent`, several volumes a GeometryCollection.
#include "EdReading.h"

// i18n: not text below (file diagnostics naming ED-318 fields and JSON paths)
namespace sortie::airspace::ed {

using namespace reading;
using mission::formats::JsonPathError;

namespace ed318 {

// The layer's limits onto `v` (no layer: the whole column).
void layer(const JsonCursor &geometry, Volume &v, GeoidAccess &geoid)
{
    const auto l = geometry.find("layer");
    if (!l || l->isNull())
        return;
    l->requireObject();
    const QString uom = single(l->at("uom")).string();
    const GeoPoint where = anchor(v);
    if (const auto lower = l->find("lower"); lower && !lower->isNull())
        v.lower = limit(*lower, uom, l->at("lowerReference"), false, where, geoid);
    if (const auto upper = l->find("upper"); upper && !upper->isNull())
        v.upper = limit(*upper, uom, l->at("upperReference"), true, where, geoid);
    checkLimits(*l, v);
}

void volumes(const JsonCursor &g, std::vector<Volume> &out, GeoidAccess &geoid, bool nested)
{
    g.requireObject();
    const QString type = g.at("type").string();
    if (type == QLatin1String("GeometryCollection")) {
        if (nested)
            g.at("type").fail(QStringLiteral("a GeometryCollection inside a GeometryCollection is not a zone volume"));
        const JsonCursor list = g.at("geometries");
        for (size_t i = 0; i < list.arraySize(); ++i)
            volumes(list.at(i), out, geoid, true);
        return;
    }
    Volume v;
    if (type == QLatin1String("Polygon")) {
        v.polygons.push_back(polygon(g.at("coordinates")));
    } else if (type == QLatin1String("MultiPolygon")) {
        const JsonCursor c = g.at("coordinates");
        for (size_t i = 0; i < c.arraySize(); ++i)
            v.polygons.push_back(polygon(c.at(i)));
        if (v.polygons.empty())
            c.fail(QStringLiteral("a MultiPolygon with no polygon"));
    } else if (type == QLatin1String("Point")) {
        const GeoPoint center = position(g.at("coordinates"));
        const auto extent = g.find("extent");
        if (!extent || extent->isNull())
            g.fail(QStringLiteral("a Point is a zone volume only with a circular extent"));
        extent->requireObject();
        const QString subType = extent->stringOr("subType", QStringLiteral("Circle"));
        if (subType != QLatin1String("Circle"))
            extent->failAt("subType", QStringLiteral("extent \"%1\" is not a Circle").arg(subType));
        const JsonCursor radius = single(extent->at("radius"));
        double r = radius.number();
        // The radius is in the layer's unit of measure, metres without a layer.
        if (const auto l = g.find("layer"); l && l->value().is_object() && l->find("uom") && l->at("uom").value().is_string()
            && l->at("uom").string().trimmed().toUpper() == QLatin1String("FT"))
            r *= 0.3048;
        if (!(r > 0))
            radius.fail(QStringLiteral("the radius must be positive"));
        v.circle = Circle{center, r};
    } else {
        g.at("type").fail(QStringLiteral("geometry %1 is not a zone volume (Polygon, MultiPolygon, Point with an extent, GeometryCollection)").arg(type));
    }
    layer(g, v, geoid);
    out.push_back(std::move(v));
}

GeoZone zone(const JsonCursor &f, GeoidAccess &geoid)
{
    f.requireObject();
    if (f.at("type").string() != QLatin1String("Feature"))
        f.at("type").fail(QStringLiteral("expected a Feature"));
    const JsonCursor p = f.at("properties");
    p.requireObject();
    GeoZone z;
    z.format = Format::Ed318;
    z.identifier = text(single(p.at("identifier")));
    if (z.identifier.trimmed().isEmpty())
        p.failAt("identifier", QStringLiteral("the zone has no identifier"));
    z.country = textOr(p, "country");
    z.name = textOr(p, "name");
    if (z.name.isEmpty())
        z.name = z.identifier;
    const JsonCursor type = single(p.at("type"));
    const QString typeName = type.string().trimmed().toUpper();
    if (typeName == QLatin1String("USPACE")) {
        // U-space airspace: a flight there needs a UAS flight authorisation from a U-space
        // service provider (EU 2021/664, Art. 10).
        z.restriction = Restriction::ReqAuthorisation;
        z.uSpaceClasses << QStringLiteral("USPACE");
    } else if (const std::optional<Restriction> r = restrictionFromName(typeName)) {
        z.restriction = *r;
    } else {
        type.fail(QStringLiteral("zone type \"%1\" is not USPACE, PROHIBITED, REQ_AUTHORIZATION, CONDITIONAL or NO_RESTRICTION").arg(type.string()));
    }
    z.restrictionConditions = p.find("restrictionConditions") && p.at("restrictionConditions").value().is_string()
        ? QStringList{p.at("restrictionConditions").string()}
        : strings(p, "restrictionConditions");
    z.reasons = strings(p, "reason");
    z.otherReasonInfo = textOr(p, "otherReasonInfo");
    z.message = textOr(p, "message");
    if (const auto applicability = p.find("limitedApplicability"); applicability && !applicability->isNull()) {
        if (applicability->value().is_object())
            z.applicability.push_back(period(*applicability));
        else
            for (size_t i = 0; i < applicability->arraySize(); ++i)
                z.applicability.push_back(period(applicability->at(i)));
    }
    if (const auto authorities = p.find("zoneAuthority"); authorities && !authorities->isNull()) {
        if (authorities->value().is_object())
            z.authorities.push_back(authority(*authorities));
        else
            for (size_t i = 0; i < authorities->arraySize(); ++i)
                z.authorities.push_back(authority(authorities->at(i)));
    }
    const JsonCursor geometry = f.at("geometry");
    if (geometry.isNull())
        geometry.fail(QStringLiteral("the feature has no geometry"));
    volumes(geometry, z.volumes, geoid, false);
    if (z.volumes.empty())
        geometry.fail(QStringLiteral("the zone has no volume"));
    return z;
}

} // namespace ed318

bool looksLikeEd318(const Json &root)
{
    if (!root.is_object() || !root.contains("type") || root["type"] != "FeatureCollection" || !root.contains("features")
        || !root["features"].is_array())
        return false;
    for (const Json &f : root["features"]) {
        if (!f.is_object() || !f.contains("properties") || !f["properties"].is_object())
            continue;
        const Json &p = f["properties"];
        if (p.contains("identifier") && (p.contains("zoneAuthority") || p.contains("variant") || p.contains("limitedApplicability")))
            return true;
    }
    return false;
}

mission::Result<GeoZoneFile> readEd318Json(const Json &root, const ReadOptions &options)
{
    GeoZoneFile out;
    out.format = Format::Ed318;
    GeoidAccess geoid(options.geoidGrid);
    try {
        const JsonCursor top(root);
        top.requireObject();
        if (top.at("type").string() != QLatin1String("FeatureCollection"))
            top.at("type").fail(QStringLiteral("an ED-318 file is a GeoJSON FeatureCollection"));
        if (const auto metadata = top.find("metadata"); metadata && metadata->value().is_object())
            if (const auto issued = metadata->find("issued"); issued && issued->value().is_string()) {
                try {
                    out.issued = dateTime(*issued);
                } catch (const JsonPathError &e) {
                    out.problems << QStringLiteral("metadata (at %1): %2").arg(QString::fromStdString(e.path), e.message);
                }
            }
        const JsonCursor features = top.at("features");
        for (size_t i = 0; i < features.arraySize(); ++i) {
            const Json &f = features.at(i).value();
            try {
                out.zones.push_back(ed318::zone(features.at(i), geoid));
            } catch (const JsonPathError &e) {
                out.problems << leftOut(featureLabel(f.is_object() && f.contains("properties") ? f["properties"] : Json(), i), e);
            }
        }
    } catch (const JsonPathError &e) {
        return mission::formats::errorAt(e);
    }
    return out;
}

mission::Result<GeoZoneFile> readEd318(const QByteArray &data, const ReadOptions &options)
{
    const mission::Result<Json> parsed = mission::formats::parseJson(data);
    if (!parsed)
        return parsed.error();
    return readEd318Json(parsed.value(), options);
}

} // namespace sortie::airspace::ed
