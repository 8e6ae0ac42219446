#include "ZoneFiles.h"

#include "EdReading.h"
#include "JsonCursor.h"

#include <cmath>

namespace sortie::airspace {

using mission::formats::Json;
using mission::formats::JsonCursor;
using mission::formats::JsonPathError;

namespace {
using ed::reading::position;

// A GeoJSON polygon, read as the geographical zones read theirs (ed::reading::polygon: rings
// closed as RFC 7946 asks, stored open, repeated vertices dropped).
ZonePolygon polygon(const JsonCursor &c) { return ZonePolygon{ed::reading::polygon(c).rings}; }

std::optional<HeightLimit> limit(const JsonCursor &props, const char *key, HeightReference reference)
{
    const auto v = props.find(key);
    if (!v || v->isNull())
        return std::nullopt;
    return HeightLimit{v->number(), reference};
}

Zone feature(const JsonCursor &f, int index, const QString &origin)
{
    f.requireObject();
    if (f.at("type").string() != QLatin1String("Feature"))
        f.at("type").fail(QStringLiteral("expected a Feature"));
    Zone z;
    z.source = ZoneSource::File;
    z.name = QStringLiteral("feature %1").arg(index + 1);
    const auto propsFound = f.find("properties");
    const Json empty = Json::object();
    const JsonCursor props = propsFound && !propsFound->isNull() ? *propsFound : JsonCursor(empty, f.path() + "/properties");
    props.requireObject();
    if (const auto name = props.find("name"); name && !name->isNull())
        z.name = name->string();
    z.origin = origin.isEmpty() ? z.name : QStringLiteral("%1, %2").arg(origin, z.name);
    const std::string kind = props.text("kind", "exclusion");
    if (kind == "exclusion")
        z.kind = ZoneKind::Exclusion;
    else if (kind == "inclusion")
        z.kind = ZoneKind::Inclusion;
    else
        props.failAt("kind", QStringLiteral("kind \"%1\" is neither \"exclusion\" nor \"inclusion\"").arg(QString::fromStdString(kind)));
    const QString reference = QString::fromStdString(props.text("reference", "AMSL")).toUpper();
    HeightReference ref = HeightReference::Amsl;
    if (reference == QLatin1String("AGL"))
        ref = HeightReference::AboveTerrain;
    else if (reference == QLatin1String("HOME"))
        ref = HeightReference::AboveHome;
    else if (reference != QLatin1String("AMSL"))
        props.failAt("reference", QStringLiteral("reference \"%1\" is not AMSL, AGL or HOME").arg(reference));
    z.floor = limit(props, "floor", ref);
    z.ceiling = limit(props, "ceiling", ref);
    if (z.floor && z.ceiling && !(z.ceiling->metres > z.floor->metres))
        props.failAt("ceiling", QStringLiteral("the ceiling (%1 m) is not above the floor (%2 m)").arg(z.ceiling->metres).arg(z.floor->metres));
    z.active = props.booleanOr("active", true);

    const JsonCursor geometry = f.at("geometry");
    if (geometry.isNull())
        geometry.fail(QStringLiteral("the feature has no geometry"));
    const QString type = geometry.at("type").string();
    const JsonCursor coordinates = geometry.at("coordinates");
    if (type == QLatin1String("Polygon")) {
        z.shape = ZonePolygons{{polygon(coordinates)}};
    } else if (type == QLatin1String("MultiPolygon")) {
        ZonePolygons parts;
        for (size_t i = 0; i < coordinates.arraySize(); ++i)
            parts.parts.push_back(polygon(coordinates.at(i)));
        if (parts.parts.empty())
            coordinates.fail(QStringLiteral("a MultiPolygon with no polygon"));
        z.shape = std::move(parts);
    } else if (type == QLatin1String("Point")) {
        const GeoPoint center = position(coordinates);
        const auto radius = props.find("radius");
        if (!radius)
            props.fail(QStringLiteral("a Point zone needs properties.radius (metres)"));
        const double r = radius->number();
        if (!(r > 0))
            radius->fail(QStringLiteral("the radius must be positive metres"));
        if (const auto top = props.find("topRadius"); top && !top->isNull()) {
            const double t = top->number();
            if (!(t >= 0))
                top->fail(QStringLiteral("the top radius must be metres, 0 or more"));
            if (!z.ceiling)
                props.fail(QStringLiteral("a cone frustum (topRadius) needs a ceiling"));
            z.shape = ZoneConeFrustum{center, r, t};
        } else {
            z.shape = ZoneCircle{center, r};
        }
    } else {
        geometry.at("type").fail(QStringLiteral("geometry %1 is not a zone (Polygon, MultiPolygon, or Point with a radius)").arg(type));
    }
    if (const QString problem = shapeProblem(z); !problem.isEmpty())
        coordinates.fail(problem);
    return z;
}

QString featureName(const Json &f, size_t index)
{
    QString label = QStringLiteral("feature %1").arg(index + 1);
    if (f.is_object() && f.contains("properties") && f["properties"].is_object() && f["properties"].contains("name")
        && f["properties"]["name"].is_string())
        label += QStringLiteral(" ('%1')").arg(QString::fromStdString(f["properties"]["name"].get<std::string>()));
    return label;
}
} // namespace

mission::Result<ZoneFile> readGeoJsonZones(const QByteArray &data, const QString &origin)
{
    mission::Result<Json> parsed = mission::formats::parseJson(data);
    if (!parsed)
        return parsed.error();
    ZoneFile out;
    try {
        const JsonCursor root(parsed.value());
        root.requireObject();
        const QString type = root.at("type").string();
        std::vector<JsonCursor> features;
        if (type == QLatin1String("Feature")) {
            features.push_back(root);
        } else if (type == QLatin1String("FeatureCollection")) {
            const JsonCursor list = root.at("features");
            for (size_t i = 0; i < list.arraySize(); ++i)
                features.push_back(list.at(i));
        } else {
            root.at("type").fail(QStringLiteral("not a GeoJSON FeatureCollection or Feature (type \"%1\")").arg(type));
        }
        for (size_t i = 0; i < features.size(); ++i) {
            try {
                out.zones.push_back(feature(features[i], int(i), origin));
            } catch (const JsonPathError &e) {
                out.problems << QStringLiteral("%1 (at %2) was left out: %3")
                                    .arg(featureName(features[i].value(), i), QString::fromStdString(e.path), e.message);
            }
        }
    } catch (const JsonPathError &e) {
        return mission::formats::errorAt(e);
    }
    return out;
}

} // namespace sortie::airspace
