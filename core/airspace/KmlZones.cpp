#include "ZoneFiles.h"

#include "NumberText.h"

#include <QRegularExpression>
#include <QXmlStreamReader>
#include <QCoreApplication>

namespace sortie::airspace {

namespace {
// "lon,lat[,alt] ..." as an open ring; an empty optional with `why` on a bad tuple.
std::optional<std::vector<GeoPoint>> ring(const QString &text, QString *why)
{
    std::vector<GeoPoint> out;
    for (const QString &tuple : text.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts)) {
        const QStringList parts = tuple.split(QLatin1Char(','));
        const auto lon = parts.size() >= 2 ? mission::formats::parseNumber(parts[0].toLatin1()) : std::nullopt;
        const auto lat = parts.size() >= 2 ? mission::formats::parseNumber(parts[1].toLatin1()) : std::nullopt;
        if (parts.size() > 3 || !lon || !lat || (parts.size() == 3 && !mission::formats::parseNumber(parts[2].toLatin1()))) {
            *why = QCoreApplication::translate("KmlZones", "bad coordinate \"%1\": expected longitude,latitude[,altitude]").arg(tuple.left(60));
            return std::nullopt;
        }
        const GeoPoint g{*lat, *lon};
        if (!g.isValid()) {
            *why = QCoreApplication::translate("KmlZones", "coordinate \"%1\" is out of range").arg(tuple.left(60));
            return std::nullopt;
        }
        out.push_back(g);
    }
    if (out.size() > 1 && out.front() == out.back())
        out.pop_back();
    if (out.size() < 3) {
        *why = QCoreApplication::translate("KmlZones", "a boundary needs at least 3 distinct coordinates, found %1").arg(out.size());
        return std::nullopt;
    }
    return out;
}
} // namespace

mission::Result<ZoneFile> readKmlZones(const QByteArray &data, const QString &origin)
{
    ZoneFile out;
    QXmlStreamReader xml(data);
    struct Placemark
    {
        QString name;
        int line = 0;
        ZonePolygons polygons;
        QString problem;
    };
    std::optional<Placemark> mark;
    int count = 0;
    bool outer = false, inner = false;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const QStringView name = xml.name();
            if (name == QLatin1String("Placemark")) {
                mark = Placemark{};
                mark->line = int(xml.lineNumber());
                ++count;
            } else if (!mark) {
                continue;
            } else if (name == QLatin1String("name") && mark->name.isEmpty()) {
                mark->name = xml.readElementText(QXmlStreamReader::IncludeChildElements).trimmed();
            } else if (name == QLatin1String("Polygon")) {
                mark->polygons.parts.emplace_back();
            } else if (name == QLatin1String("outerBoundaryIs")) {
                outer = true;
            } else if (name == QLatin1String("innerBoundaryIs")) {
                inner = true;
            } else if (name == QLatin1String("coordinates") && (outer || inner) && !mark->polygons.parts.empty()) {
                const int line = int(xml.lineNumber());
                QString why;
                const auto points = ring(xml.readElementText(), &why);
                if (!points && mark->problem.isEmpty())
                    mark->problem = QCoreApplication::translate("KmlZones", "line %1: %2").arg(line).arg(why);
                if (!points)
                    continue;
                auto &rings = mark->polygons.parts.back().rings;
                if (outer && !rings.empty() && mark->problem.isEmpty())
                    mark->problem = QCoreApplication::translate("KmlZones", "line %1: a polygon with two outer boundaries").arg(line);
                if (inner && rings.empty() && mark->problem.isEmpty())
                    mark->problem = QCoreApplication::translate("KmlZones", "line %1: an inner boundary before the outer one").arg(line);
                rings.push_back(*points);
            }
        } else if (xml.isEndElement()) {
            const QStringView name = xml.name();
            if (name == QLatin1String("outerBoundaryIs"))
                outer = false;
            else if (name == QLatin1String("innerBoundaryIs"))
                inner = false;
            else if (name == QLatin1String("Placemark") && mark) {
                const QString label = mark->name.isEmpty() ? QCoreApplication::translate("KmlZones", "Placemark %1").arg(count)
                                                           : QCoreApplication::translate("KmlZones", "Placemark '%1'").arg(mark->name);
                for (const ZonePolygon &p : mark->polygons.parts)
                    if (p.rings.empty() && mark->problem.isEmpty())
                        mark->problem = QCoreApplication::translate("KmlZones", "a Polygon without an outer boundary");
                if (mark->problem.isEmpty() && !mark->polygons.parts.empty()) {
                    Zone probe;
                    probe.shape = mark->polygons;
                    mark->problem = shapeProblem(probe);
                }
                if (!mark->problem.isEmpty()) {
                    out.problems << QCoreApplication::translate("KmlZones", "%1 (line %2) was left out: %3").arg(label).arg(mark->line).arg(mark->problem);
                } else if (!mark->polygons.parts.empty()) {  // a placemark without a polygon (a point, a path) is no zone
                    Zone z;
                    z.name = mark->name.isEmpty() ? QCoreApplication::translate("KmlZones", "Placemark %1").arg(count) : mark->name;
                    z.kind = ZoneKind::Exclusion;
                    z.shape = std::move(mark->polygons);
                    z.origin = origin.isEmpty() ? z.name : QStringLiteral("%1, %2").arg(origin, z.name);
                    out.zones.push_back(std::move(z));
                }
                mark.reset();
            }
        }
    }
    if (xml.hasError())
        return mission::MissionError{QCoreApplication::translate("KmlZones", "not well-formed KML: %1").arg(xml.errorString()), {}, int(xml.lineNumber()),
                                     int(xml.columnNumber()), {}};
    return out;
}

} // namespace sortie::airspace
