#include "KmlFormat.h"

#include "FlightPath.h"
#include "NumberText.h"

#include <QXmlStreamReader>
#include <QXmlStreamWriter>
#include <QCoreApplication>

namespace sortie::mission::formats {

namespace {
MissionError xmlError(int line, int column, const QString &message)
{
    return MissionError{message, {}, line, column, {}};
}

// Parses "lon,lat[,alt] lon,lat[,alt] ..." that starts on startLine.
Result<std::vector<GeoPoint>> parseCoordinates(const QString &text, int startLine)
{
    std::vector<GeoPoint> out;
    int line = startLine;
    qsizetype i = 0;
    const qsizetype n = text.size();
    while (i < n) {
        while (i < n && text[i].isSpace()) {
            if (text[i] == QLatin1Char('\n')) ++line;
            ++i;
        }
        const qsizetype start = i;
        while (i < n && !text[i].isSpace())
            ++i;
        if (i == start)
            break;
        const QString tuple = text.mid(start, i - start);
        const QStringList parts = tuple.split(QLatin1Char(','));
        if (parts.size() < 2 || parts.size() > 3)
            return xmlError(line, 0, QCoreApplication::translate("KmlFormat", "bad coordinate \"%1\": expected longitude,latitude[,altitude]").arg(tuple.left(60)));
        const auto lon = parseNumber(parts[0].toLatin1()), lat = parseNumber(parts[1].toLatin1());
        if (!lon || !lat || (parts.size() == 3 && !parseNumber(parts[2].toLatin1())))
            return xmlError(line, 0, QCoreApplication::translate("KmlFormat", "bad coordinate \"%1\": not a number").arg(tuple.left(60)));
        const GeoPoint g{*lat, *lon};
        if (!g.isValid())
            return xmlError(line, 0, QCoreApplication::translate("KmlFormat", "coordinate \"%1\" is out of range").arg(tuple.left(60)));
        out.push_back(g);
    }
    return out;
}

void writeCoordinates(QXmlStreamWriter &w, const std::vector<std::pair<GeoPoint, double>> &points)
{
    QByteArray text;
    for (const auto &[g, alt] : points)
        text += shortestNumber(g.longitude) + ',' + shortestNumber(g.latitude) + ',' + shortestNumber(alt) + ' ';
    text.chop(1);
    w.writeTextElement(QStringLiteral("coordinates"), QString::fromLatin1(text));
}

QString altitudeMode(AltitudeType t) { return t == AltitudeType::Agl ? QStringLiteral("relativeToGround") : QStringLiteral("absolute"); }
}

Result<ImportedPolygon> readKmlPolygon(const QByteArray &data)
{
    struct Shape { bool polygon; bool closed; int line; std::vector<GeoPoint> points; QString name; };
    std::vector<Shape> shapes;
    QXmlStreamReader xml(data);
    QString placemarkName;
    int placemarkLine = 0;
    QString context;  // "Polygon" or "LineString": where a <coordinates> counts
    int depthInOuter = 0;
    bool inPlacemark = false;
    bool placemarkHasGeometry = false;
    int firstBarePlacemarkLine = 0;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const QStringView name = xml.name();
            if (name == QLatin1String("Placemark")) {
                inPlacemark = true;
                placemarkHasGeometry = false;
                placemarkName.clear();
                placemarkLine = int(xml.lineNumber());
            } else if (name == QLatin1String("name") && inPlacemark && placemarkName.isEmpty()) {
                placemarkName = xml.readElementText(QXmlStreamReader::SkipChildElements).trimmed();
            } else if (name == QLatin1String("outerBoundaryIs")) {
                ++depthInOuter;
            } else if (name == QLatin1String("LinearRing") && depthInOuter > 0) {
                context = QStringLiteral("Polygon");
            } else if (name == QLatin1String("LineString")) {
                context = QStringLiteral("LineString");
            } else if (name == QLatin1String("Polygon") || name == QLatin1String("Point")) {
                placemarkHasGeometry = true;
            } else if (name == QLatin1String("coordinates") && !context.isEmpty()) {
                placemarkHasGeometry = true;
                const int line = int(xml.lineNumber());
                const QString text = xml.readElementText();
                if (xml.hasError())
                    break;
                Result<std::vector<GeoPoint>> pts = parseCoordinates(text, line);
                if (!pts)
                    return pts.error();
                std::vector<GeoPoint> ring = std::move(pts).value();
                const bool closed = ring.size() > 1 && ring.front() == ring.back();
                if (closed)
                    ring.pop_back();
                if (ring.size() < 3 && (closed || context == QLatin1String("Polygon")))
                    return xmlError(line, 0, QCoreApplication::translate("KmlFormat", "a boundary needs at least 3 distinct points, found %1").arg(ring.size()));
                shapes.push_back({context == QLatin1String("Polygon"), closed, line, std::move(ring), placemarkName});
                context.clear();
            }
        } else if (xml.isEndElement()) {
            const QStringView name = xml.name();
            if (name == QLatin1String("outerBoundaryIs"))
                --depthInOuter;
            else if (name == QLatin1String("LinearRing") || name == QLatin1String("LineString"))
                context.clear();
            else if (name == QLatin1String("Placemark")) {
                if (!placemarkHasGeometry && !firstBarePlacemarkLine)
                    firstBarePlacemarkLine = placemarkLine;
                inPlacemark = false;
            }
        }
    }
    if (xml.hasError())
        return xmlError(int(xml.lineNumber()), int(xml.columnNumber()), QCoreApplication::translate("KmlFormat", "not valid KML: %1").arg(xml.errorString()));
    // A Polygon first; else a closed LineString.
    const Shape *chosen = nullptr;
    int usable = 0;
    for (const Shape &sh : shapes) {
        if (!sh.polygon && !sh.closed)
            continue;
        ++usable;
        if (!chosen || (sh.polygon && !chosen->polygon))
            chosen = &sh;
    }
    if (!chosen) {
        for (const Shape &sh : shapes)
            return xmlError(sh.line, 0, QCoreApplication::translate("KmlFormat", "this LineString is open, so it encloses no area; close it (last point = first) to use it as a boundary"));
        if (firstBarePlacemarkLine)
            return xmlError(firstBarePlacemarkLine, 0, QCoreApplication::translate("KmlFormat", "this Placemark has no Polygon (with an outerBoundaryIs LinearRing) or closed LineString"));
        return xmlError(int(xml.lineNumber()), 0, QCoreApplication::translate("KmlFormat", "the document has no Polygon or closed LineString"));
    }
    ImportedPolygon out;
    out.name = chosen->name;
    out.polygon = chosen->points;
    if (usable > 1)
        out.notices << QCoreApplication::translate("KmlFormat", "The file holds %1 closed shapes; the one at line %2 was imported.").arg(usable).arg(chosen->line);
    return out;
}

QByteArray writeKmlRoute(const Route &route, ScanPlanCache *cache)
{
    QByteArray bytes;
    QXmlStreamWriter w(&bytes);
    w.setAutoFormatting(true);
    w.setAutoFormattingIndent(1);
    w.writeStartDocument();
    w.writeStartElement(QStringLiteral("kml"));
    w.writeDefaultNamespace(QStringLiteral("http://www.opengis.net/kml/2.2"));
    w.writeStartElement(QStringLiteral("Document"));
    w.writeTextElement(QStringLiteral("name"), route.settings.name.isEmpty() ? QStringLiteral("Route") : route.settings.name);

    const std::vector<PathPoint> path = flightPath(route, cache);
    size_t i = 0;
    int part = 0;
    while (i < path.size()) {
        // A run of points with one altitude type; it starts at the previous run's last point so the line is continuous.
        const AltitudeType t = path[i].altitudeType;
        std::vector<std::pair<GeoPoint, double>> run;
        if (i > 0)
            run.emplace_back(path[i - 1].position, path[i - 1].altitude);
        while (i < path.size() && path[i].altitudeType == t) {
            run.emplace_back(path[i].position, path[i].altitude);
            ++i;
        }
        w.writeStartElement(QStringLiteral("Placemark"));
        w.writeTextElement(QStringLiteral("name"), part++ == 0 && i == path.size() ? QCoreApplication::translate("KmlFormat", "Flight path")
                                                                                  : QCoreApplication::translate("KmlFormat", "Flight path, part %1").arg(part));
        w.writeStartElement(QStringLiteral("LineString"));
        w.writeTextElement(QStringLiteral("altitudeMode"), altitudeMode(t));
        writeCoordinates(w, run);
        w.writeEndElement();
        w.writeEndElement();
    }

    w.writeStartElement(QStringLiteral("Folder"));
    w.writeTextElement(QStringLiteral("name"), QStringLiteral("Waypoints"));
    for (size_t row = 0; row < route.segments.size(); ++row) {
        const Segment &s = route.segments[row];
        w.writeStartElement(QStringLiteral("Placemark"));
        w.writeTextElement(QStringLiteral("name"), QString::number(row + 1));
        if (const Waypoint *wp = asWaypoint(s)) {
            if (!wp->actions.empty())
                w.writeTextElement(QStringLiteral("description"), describeActions(wp->actions));
            w.writeStartElement(QStringLiteral("Point"));
            w.writeTextElement(QStringLiteral("altitudeMode"), altitudeMode(wp->altitudeType));
            writeCoordinates(w, {{wp->position, wp->altitude}});
            w.writeEndElement();
        } else {
            // Areas as polygons; a corridor's line and a circle's centre as a (one-point) ring.
            std::vector<std::pair<GeoPoint, double>> ring;
            for (const GeoPoint &g : figureOf(s))
                ring.emplace_back(g, 0.0);
            if (!ring.empty())
                ring.push_back(ring.front());
            w.writeStartElement(QStringLiteral("Polygon"));
            w.writeTextElement(QStringLiteral("altitudeMode"), QStringLiteral("clampToGround"));
            w.writeStartElement(QStringLiteral("outerBoundaryIs"));
            w.writeStartElement(QStringLiteral("LinearRing"));
            writeCoordinates(w, ring);
            w.writeEndElement();
            w.writeEndElement();
            w.writeEndElement();
        }
        w.writeEndElement();
    }
    w.writeEndElement();  // Folder
    w.writeEndElement();  // Document
    w.writeEndElement();  // kml
    w.writeEndDocument();
    return bytes;
}

} // namespace sortie::mission::formats
