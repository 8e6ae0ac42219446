// Reading a WPML document's XML into plain values, recording every element it does not use.
#include "WpmlDocumentReader.h"

#include "NumberText.h"

#include <QXmlStreamReader>

#include <set>
#include <QCoreApplication>

namespace sortie::mission::formats::wpml {
namespace {

MissionError errorAt(const QString &file, const QXmlStreamReader &x, const QString &message)
{
    return MissionError{message, file, int(x.lineNumber()), int(x.columnNumber()), {}};
}

bool is(QStringView name, const char *what) { return name == QLatin1String(what); }

// Elements whose meaning the export rebuilds from the route (ids, totals, the template's editing
// defaults already resolved per waypoint): skipped without a notice.
const std::set<QString> &rebuilt()
{
    static const std::set<QString> names = {
        QStringLiteral("author"), QStringLiteral("createTime"), QStringLiteral("updateTime"),
        QStringLiteral("templateId"), QStringLiteral("waylineId"), QStringLiteral("distance"), QStringLiteral("duration"),
        QStringLiteral("autoFlightSpeed"), QStringLiteral("coordinateMode"), QStringLiteral("globalHeight"),
        QStringLiteral("caliFlightEnable"), QStringLiteral("gimbalPitchMode"), QStringLiteral("globalWaypointHeadingParam"),
        QStringLiteral("globalWaypointTurnMode"), QStringLiteral("globalUseStraightLine"), QStringLiteral("payloadParam"),
        QStringLiteral("useGlobalHeight"), QStringLiteral("useGlobalSpeed"), QStringLiteral("useGlobalHeadingParam"),
        QStringLiteral("useGlobalTurnParam"), QStringLiteral("ellipsoidHeight"), QStringLiteral("waypointTurnDampingDist"),
        QStringLiteral("waypointHeadingPathMode"), QStringLiteral("actionGroupId"), QStringLiteral("actionGroupMode"),
        QStringLiteral("actionId"), QStringLiteral("payloadPositionIndex"), QStringLiteral("payloadSubEnumValue"),
    };
    return names;
}

// missionConfig values the export writes as they are here: a file with another value is told.
const std::map<QString, QString> &writtenAs()
{
    static const std::map<QString, QString> values = {
        {QStringLiteral("flyToWaylineMode"), QStringLiteral("safely")},
        {QStringLiteral("exitOnRCLost"), QStringLiteral("executeLostAction")},
        {QStringLiteral("executeRCLostAction"), QStringLiteral("goBack")},
        {QStringLiteral("takeOffSecurityHeight"), QStringLiteral("20")},
    };
    return values;
}

class DocumentReader
{
public:
    DocumentReader(const QByteArray &data, QString file) : x(data), m_file(std::move(file)) {}

    Result<ReadDocument> read()
    {
        ReadDocument doc;
        while (x.readNextStartElement()) {
            if (is(name(), "kml") || is(name(), "Document"))
                continue;  // descend
            if (is(name(), "missionConfig")) {
                readMissionConfig(doc);
            } else if (is(name(), "Folder")) {
                ReadFolder f = readFolder();
                if (m_error)
                    return *m_error;
                doc.folders.push_back(std::move(f));
            } else {
                skip(&doc.unknown);
            }
            if (m_error)
                return *m_error;
        }
        if (x.hasError())
            return errorAt(m_file, x, QCoreApplication::translate("WpmlDocumentReader", "malformed XML: %1").arg(x.errorString()));
        doc.unknown.removeDuplicates();
        return doc;
    }

private:
    QStringView name() const { return x.name(); }
    QString text() { return x.readElementText(QXmlStreamReader::SkipChildElements).trimmed(); }

    // Skips an element, naming it unless the export rebuilds it.
    void skip(QStringList *unknown)
    {
        const QString local = name().toString(), qualified = x.qualifiedName().toString();
        x.skipCurrentElement();
        if (!rebuilt().count(local))
            unknown->append(qualified);
    }
    void skip(ReadFolder &f, int waypoint)
    {
        const QString local = name().toString(), qualified = x.qualifiedName().toString();
        x.skipCurrentElement();
        if (!rebuilt().count(local))
            f.unknown[qualified].push_back(waypoint);
    }

    std::optional<double> number(const QString &what)
    {
        const QString t = text();
        const auto v = parseNumber(t.toLatin1());
        if (!v && !m_error)
            m_error = errorAt(m_file, x, QCoreApplication::translate("WpmlDocumentReader", "%1 is not a number: \"%2\"").arg(what, t));
        return v;
    }

    std::optional<int> whole(const QString &what)
    {
        bool ok = false;
        const QString t = text();
        const int v = t.toInt(&ok);
        if (!ok && !m_error)
            m_error = errorAt(m_file, x, QCoreApplication::translate("WpmlDocumentReader", "%1 is not a whole number: \"%2\"").arg(what, t));
        return ok ? std::optional<int>(v) : std::nullopt;
    }

    void readMissionConfig(ReadDocument &doc)
    {
        while (x.readNextStartElement() && !m_error) {
            const QStringView n = name();
            if (is(n, "finishAction")) {
                doc.finishAction = text();
            } else if (is(n, "globalTransitionalSpeed")) {
                doc.transitionalSpeed = number(QStringLiteral("globalTransitionalSpeed"));
            } else if (is(n, "takeOffRefPoint")) {
                doc.takeOffRefPoint = text();
            } else if (is(n, "takeOffRefPointAGLHeight")) {
                doc.takeOffRefPointAglHeight = number(QStringLiteral("takeOffRefPointAGLHeight"));
            } else if (is(n, "droneInfo") || is(n, "payloadInfo")) {
                while (x.readNextStartElement() && !m_error) {
                    if (is(name(), "droneEnumValue"))
                        doc.droneEnum = whole(QStringLiteral("droneEnumValue"));
                    else if (is(name(), "droneSubEnumValue"))
                        doc.droneSubEnum = whole(QStringLiteral("droneSubEnumValue"));
                    else if (is(name(), "payloadEnumValue"))
                        doc.payloadEnum = whole(QStringLiteral("payloadEnumValue"));
                    else
                        skip(&doc.unknown);
                }
            } else if (const auto it = writtenAs().find(n.toString()); it != writtenAs().end()) {
                const QString qualified = x.qualifiedName().toString();
                const QString value = text();
                if (value != it->second)
                    doc.unknown << QCoreApplication::translate("WpmlDocumentReader", "%1 \"%2\" (written as \"%3\")").arg(qualified, value, it->second);
            } else {
                skip(&doc.unknown);
            }
        }
    }

    ReadFolder readFolder()
    {
        ReadFolder f;
        while (x.readNextStartElement() && !m_error) {
            const QStringView n = name();
            if (is(n, "executeHeightMode")) {
                f.heightMode = text();
            } else if (is(n, "templateType")) {
                f.templateType = text();
            } else if (is(n, "waylineCoordinateSysParam")) {
                while (x.readNextStartElement()) {
                    if (is(name(), "heightMode"))
                        f.heightMode = text();
                    else
                        skip(f, 0);
                }
            } else if (is(n, "startActionGroup")) {
                f.startGroup = readGroup();
            } else if (is(n, "Placemark")) {
                ReadPoint p = readPlacemark(f);
                if (!m_error)
                    f.points.push_back(std::move(p));
            } else {
                skip(f, 0);
            }
        }
        return f;
    }

    ReadPoint readPlacemark(ReadFolder &f)
    {
        ReadPoint p;
        p.line = int(x.lineNumber());
        const int pointNumber = int(f.points.size()) + 1;  // for naming unknown elements: the order in the file
        while (x.readNextStartElement() && !m_error) {
            const QStringView n = name();
            if (is(n, "Point")) {
                while (x.readNextStartElement()) {
                    if (!is(name(), "coordinates")) {
                        skip(f, pointNumber);
                        continue;
                    }
                    const QString t = text();
                    const QStringList parts = t.split(QLatin1Char(','));
                    const auto lon = parts.size() >= 2 ? parseNumber(parts[0].trimmed().toLatin1()) : std::nullopt;
                    const auto lat = parts.size() >= 2 ? parseNumber(parts[1].trimmed().toLatin1()) : std::nullopt;
                    const GeoPoint g{lat.value_or(1000.0), lon.value_or(1000.0)};
                    if (!lat || !lon || !g.isValid()) {
                        m_error = errorAt(m_file, x, QCoreApplication::translate("WpmlDocumentReader", "coordinates \"%1\" are not longitude,latitude in degrees").arg(t));
                        return p;
                    }
                    p.position = g;
                }
            } else if (is(n, "index")) {
                bool ok = false;
                p.index = text().toInt(&ok);
                if (!ok) {
                    m_error = errorAt(m_file, x, QCoreApplication::translate("WpmlDocumentReader", "a waypoint index is not a whole number"));
                    return p;
                }
            } else if (is(n, "executeHeight") || is(n, "height")) {
                p.height = number(n.toString());
            } else if (is(n, "waypointSpeed")) {
                p.speed = number(QStringLiteral("waypointSpeed"));
            } else if (is(n, "useStraightLine")) {
                p.straight = text() != QLatin1String("0");
            } else if (is(n, "waypointHeadingParam")) {
                while (x.readNextStartElement()) {
                    if (is(name(), "waypointHeadingMode"))
                        p.headingMode = text();
                    else if (is(name(), "waypointHeadingAngle"))
                        p.headingAngle = text();
                    else if (is(name(), "waypointPoiPoint"))
                        p.poi = text();
                    else
                        skip(f, pointNumber);
                }
            } else if (is(n, "waypointTurnParam")) {
                while (x.readNextStartElement()) {
                    if (is(name(), "waypointTurnMode"))
                        p.turnMode = text();
                    else
                        skip(f, pointNumber);
                }
            } else if (is(n, "actionGroup")) {
                p.groups.push_back(readGroup());
            } else {
                skip(f, pointNumber);
            }
        }
        return p;
    }

    ReadGroup readGroup()
    {
        ReadGroup g;
        while (x.readNextStartElement() && !m_error) {
            const QStringView n = name();
            if (is(n, "actionGroupStartIndex")) {
                g.start = text().toInt();
            } else if (is(n, "actionGroupEndIndex")) {
                g.end = text().toInt();
            } else if (is(n, "actionTrigger")) {
                while (x.readNextStartElement()) {
                    if (is(name(), "actionTriggerType"))
                        g.trigger = text();
                    else if (is(name(), "actionTriggerParam"))
                        g.interval = number(QStringLiteral("actionTriggerParam"));
                    else
                        x.skipCurrentElement();
                }
            } else if (is(n, "action")) {
                ReadAction a;
                while (x.readNextStartElement()) {
                    if (is(name(), "actionActuatorFunc")) {
                        a.func = text();
                    } else if (is(name(), "actionActuatorFuncParam")) {
                        while (x.readNextStartElement()) {
                            const QString key = name().toString();
                            a.params[key] = text();
                        }
                    } else {
                        x.skipCurrentElement();
                    }
                }
                g.actions.push_back(std::move(a));
            } else {
                x.skipCurrentElement();
            }
        }
        return g;
    }

    QXmlStreamReader x;
    QString m_file;
    std::optional<MissionError> m_error;
};

} // namespace

Result<ReadDocument> readDocument(const QByteArray &data, const QString &file)
{
    return DocumentReader(data, file).read();
}

} // namespace sortie::mission::formats::wpml
