// Printing a WPML plan as DJI's XML: the mission config, the placemarks and their action groups.
#include "WpmlDocuments.h"

#include "NumberText.h"

#include <QXmlStreamWriter>

#include <cmath>

namespace sortie::mission::formats::wpml {
namespace {

QString num(double v) { return QString::fromLatin1(shortestNumber(v)); }
// Degrees to 1e-9 (0.1 mm), trailing zeros dropped: "24.0735".
QString coord(double v)
{
    QString s = QString::number(v, 'f', 9);
    qsizetype end = s.size();
    while (end > 0 && s[end - 1] == QLatin1Char('0'))
        --end;
    if (end > 0 && s[end - 1] == QLatin1Char('.'))
        --end;
    s.truncate(end);
    return s;
}

class Writer
{
public:
    Writer(QByteArray *out) : x(out) { x.setAutoFormatting(true); x.setAutoFormattingIndent(2); }
    void el(const QString &name, const QString &text) { x.writeTextElement(kNamespace, name, text); }
    void el(const QString &name, double v) { el(name, num(v)); }
    void begin(const QString &name) { x.writeStartElement(kNamespace, name); }
    void kmlBegin(const QString &name) { x.writeStartElement(kKmlNamespace, name); }
    void end() { x.writeEndElement(); }
    QXmlStreamWriter x;
};

void writeDocumentStart(Writer &w)
{
    w.x.writeStartDocument();
    w.x.writeDefaultNamespace(kKmlNamespace);  // <kml xmlns="...">, unprefixed, as DJI's own files are
    w.x.writeNamespace(kNamespace, QStringLiteral("wpml"));
    w.kmlBegin(QStringLiteral("kml"));
    w.kmlBegin(QStringLiteral("Document"));
}

void writeMissionConfig(Writer &w, const Mission &mission, const WpmlExportOptions &o, const DjiDroneModel &model,
                        const DjiPayload &payload, bool withTakeoff)
{
    w.begin(QStringLiteral("missionConfig"));
    w.el(QStringLiteral("flyToWaylineMode"), QStringLiteral("safely"));
    w.el(QStringLiteral("finishAction"), finishActionName(mission.waylines.back().plan->finish));
    w.el(QStringLiteral("exitOnRCLost"), QStringLiteral("executeLostAction"));
    w.el(QStringLiteral("executeRCLostAction"), QStringLiteral("goBack"));
    w.el(QStringLiteral("takeOffSecurityHeight"), o.takeoffSecurityHeight);
    if (withTakeoff && !mission.takeOffRefPoint.isEmpty())
        w.el(QStringLiteral("takeOffRefPoint"), mission.takeOffRefPoint);
    w.el(QStringLiteral("globalTransitionalSpeed"), mission.waylines.front().plan->points.front().speed);
    w.begin(QStringLiteral("droneInfo"));
    w.el(QStringLiteral("droneEnumValue"), QString::number(model.droneEnumValue));
    w.el(QStringLiteral("droneSubEnumValue"), QString::number(model.droneSubEnumValue));
    w.end();
    w.begin(QStringLiteral("payloadInfo"));
    w.el(QStringLiteral("payloadEnumValue"), QString::number(payload.enumValue));
    w.el(QStringLiteral("payloadSubEnumValue"), QString::number(payload.subEnumValue));
    w.el(QStringLiteral("payloadPositionIndex"), QStringLiteral("0"));
    w.end();
    w.end();
}

void writeAction(Writer &w, int id, const Action &a)
{
    w.begin(QStringLiteral("action"));
    w.el(QStringLiteral("actionId"), QString::number(id));
    w.el(QStringLiteral("actionActuatorFunc"), actuatorFuncName(a.func));
    w.begin(QStringLiteral("actionActuatorFuncParam"));
    switch (a.func) {
    case ActuatorFunc::TakePhoto:
    case ActuatorFunc::StartRecord:
        w.el(QStringLiteral("payloadPositionIndex"), QStringLiteral("0"));
        w.el(QStringLiteral("useGlobalPayloadLensIndex"), QStringLiteral("1"));
        break;
    case ActuatorFunc::StopRecord:
        w.el(QStringLiteral("payloadPositionIndex"), QStringLiteral("0"));
        break;
    case ActuatorFunc::GimbalRotate:
        w.el(QStringLiteral("gimbalHeadingYawBase"), QStringLiteral("aircraft"));
        w.el(QStringLiteral("gimbalRotateMode"), QStringLiteral("absoluteAngle"));
        w.el(QStringLiteral("gimbalPitchRotateEnable"), QStringLiteral("1"));
        w.el(QStringLiteral("gimbalPitchRotateAngle"), a.value);
        w.el(QStringLiteral("gimbalRollRotateEnable"), QStringLiteral("0"));
        w.el(QStringLiteral("gimbalRollRotateAngle"), QStringLiteral("0"));
        w.el(QStringLiteral("gimbalYawRotateEnable"), QStringLiteral("0"));
        w.el(QStringLiteral("gimbalYawRotateAngle"), QStringLiteral("0"));
        w.el(QStringLiteral("gimbalRotateTimeEnable"), QStringLiteral("0"));
        w.el(QStringLiteral("gimbalRotateTime"), QStringLiteral("0"));
        w.el(QStringLiteral("payloadPositionIndex"), QStringLiteral("0"));
        break;
    case ActuatorFunc::RotateYaw:
        w.el(QStringLiteral("aircraftHeading"), a.value);
        w.el(QStringLiteral("aircraftPathMode"), QStringLiteral("clockwise"));
        break;
    case ActuatorFunc::Hover:
        w.el(QStringLiteral("hoverTime"), a.value);
        break;
    }
    w.end();
    w.end();
}

void writeGroups(Writer &w, const Plan &plan, int k, int *groupId)
{
    for (const Group &g : plan.groups) {
        if (g.start != k)
            continue;
        w.begin(QStringLiteral("actionGroup"));
        w.el(QStringLiteral("actionGroupId"), QString::number((*groupId)++));
        w.el(QStringLiteral("actionGroupStartIndex"), QString::number(g.start));
        w.el(QStringLiteral("actionGroupEndIndex"), QString::number(g.end));
        w.el(QStringLiteral("actionGroupMode"), QStringLiteral("sequence"));
        w.begin(QStringLiteral("actionTrigger"));
        w.el(QStringLiteral("actionTriggerType"), triggerTypeName(g.trigger));
        if (g.trigger != TriggerType::ReachPoint)
            w.el(QStringLiteral("actionTriggerParam"), g.interval);
        w.end();
        int actionId = 0;
        for (const Action &a : g.actions)
            writeAction(w, actionId++, a);
        w.end();
    }
}

void writeHeadingAndTurn(Writer &w, const Point &p)
{
    w.begin(QStringLiteral("waypointHeadingParam"));
    w.el(QStringLiteral("waypointHeadingMode"), headingModeName(p.heading));
    w.el(QStringLiteral("waypointHeadingAngle"), QStringLiteral("0"));
    if (p.poi)
        w.el(QStringLiteral("waypointPoiPoint"), QStringLiteral("%1,%2,%3").arg(coord((*p.poi)[0]), coord((*p.poi)[1]), num((*p.poi)[2])));
    else
        w.el(QStringLiteral("waypointPoiPoint"), QStringLiteral("0.000000,0.000000,0.000000"));
    w.el(QStringLiteral("waypointHeadingPathMode"), QStringLiteral("followBadArc"));
    w.end();
    w.begin(QStringLiteral("waypointTurnParam"));
    w.el(QStringLiteral("waypointTurnMode"), turnModeName(p.turn));
    w.el(QStringLiteral("waypointTurnDampingDist"), p.turn == TurnMode::Coordinated ? p.damping : 0.0);
    w.end();
    w.el(QStringLiteral("useStraightLine"), p.straight ? QStringLiteral("1") : QStringLiteral("0"));
}

void writePoint(Writer &w, const Point &p)
{
    w.kmlBegin(QStringLiteral("Point"));
    w.x.writeTextElement(kKmlNamespace, QStringLiteral("coordinates"),
                         QStringLiteral("%1,%2").arg(coord(p.position.longitude), coord(p.position.latitude)));
    w.end();
}

// DJI's waypointSpeed is the speed from a waypoint to the next; Sortie's is the speed arriving.
double departingSpeed(const Plan &plan, size_t k)
{
    return k + 1 < plan.points.size() ? plan.points[k + 1].speed : plan.points[k].speed;
}

// wpml:startActionGroup: the actions before the flight to the first waypoint.
void writeStartGroup(Writer &w, const Plan &plan)
{
    if (plan.startActions.empty())
        return;
    w.begin(QStringLiteral("startActionGroup"));
    int actionId = 0;
    for (const Action &a : plan.startActions)
        writeAction(w, actionId++, a);
    w.end();
}

void writeWaylineFolder(Writer &w, const Wayline &wayline, int id, const WpmlExportOptions &o, int *groupId)
{
    const Plan &plan = *wayline.plan;
    w.kmlBegin(QStringLiteral("Folder"));
    w.el(QStringLiteral("templateId"), QString::number(id));
    w.el(QStringLiteral("executeHeightMode"), executeHeightModeName(o.heightMode));
    w.el(QStringLiteral("waylineId"), QString::number(id));
    w.el(QStringLiteral("distance"), std::round(wayline.distance * 10.0) / 10.0);
    w.el(QStringLiteral("duration"), std::round(wayline.duration * 10.0) / 10.0);
    w.el(QStringLiteral("autoFlightSpeed"), departingSpeed(plan, 0));
    writeStartGroup(w, plan);
    for (size_t k = 0; k < plan.points.size(); ++k) {
        const Point &p = plan.points[k];
        w.kmlBegin(QStringLiteral("Placemark"));
        writePoint(w, p);
        w.el(QStringLiteral("index"), QString::number(k));
        w.el(QStringLiteral("executeHeight"), p.executeHeight);
        w.el(QStringLiteral("waypointSpeed"), departingSpeed(plan, k));
        writeHeadingAndTurn(w, p);
        writeGroups(w, plan, int(k), groupId);
        w.end();
    }
    w.end();
}

void writeTemplateFolder(Writer &w, const Plan &plan, int id, const WpmlExportOptions &o, int *groupId)
{
    w.kmlBegin(QStringLiteral("Folder"));
    w.el(QStringLiteral("templateType"), QStringLiteral("waypoint"));
    w.el(QStringLiteral("templateId"), QString::number(id));
    w.begin(QStringLiteral("waylineCoordinateSysParam"));
    w.el(QStringLiteral("coordinateMode"), QStringLiteral("WGS84"));
    w.el(QStringLiteral("heightMode"), templateHeightModeName(o.heightMode));
    w.end();
    w.el(QStringLiteral("autoFlightSpeed"), departingSpeed(plan, 0));
    w.el(QStringLiteral("globalHeight"), plan.points.front().templateHeight);
    w.el(QStringLiteral("caliFlightEnable"), QStringLiteral("0"));
    w.el(QStringLiteral("gimbalPitchMode"), QStringLiteral("manual"));
    w.begin(QStringLiteral("globalWaypointHeadingParam"));
    w.el(QStringLiteral("waypointHeadingMode"), QStringLiteral("followWayline"));
    w.el(QStringLiteral("waypointHeadingAngle"), QStringLiteral("0"));
    w.el(QStringLiteral("waypointPoiPoint"), QStringLiteral("0.000000,0.000000,0.000000"));
    w.el(QStringLiteral("waypointHeadingPathMode"), QStringLiteral("followBadArc"));
    w.end();
    w.el(QStringLiteral("globalWaypointTurnMode"), turnModeName(TurnMode::StopStraight));
    w.el(QStringLiteral("globalUseStraightLine"), QStringLiteral("1"));
    for (size_t k = 0; k < plan.points.size(); ++k) {
        const Point &p = plan.points[k];
        w.kmlBegin(QStringLiteral("Placemark"));
        writePoint(w, p);
        w.el(QStringLiteral("index"), QString::number(k));
        w.el(QStringLiteral("height"), p.templateHeight);
        w.el(QStringLiteral("useGlobalHeight"), QStringLiteral("0"));
        w.el(QStringLiteral("useGlobalSpeed"), QStringLiteral("0"));
        w.el(QStringLiteral("waypointSpeed"), departingSpeed(plan, k));
        w.el(QStringLiteral("useGlobalHeadingParam"), QStringLiteral("0"));
        w.el(QStringLiteral("useGlobalTurnParam"), QStringLiteral("0"));
        writeHeadingAndTurn(w, p);
        writeGroups(w, plan, int(k), groupId);
        w.end();
    }
    w.begin(QStringLiteral("payloadParam"));
    w.el(QStringLiteral("payloadPositionIndex"), QStringLiteral("0"));
    w.el(QStringLiteral("imageFormat"), QStringLiteral("wide"));
    w.end();
    w.end();
}

} // namespace

QByteArray waylinesOf(const Mission &mission, const WpmlExportOptions &o, const DjiDroneModel &model, const DjiPayload &payload)
{
    QByteArray out;
    Writer w(&out);
    writeDocumentStart(w);
    writeMissionConfig(w, mission, o, model, payload, false);
    int groupId = 0;  // unique within the file
    for (size_t f = 0; f < mission.waylines.size(); ++f)
        writeWaylineFolder(w, mission.waylines[f], int(f), o, &groupId);
    w.end();
    w.end();
    w.x.writeEndDocument();
    return out;
}

QByteArray templateOf(const Mission &mission, const WpmlExportOptions &o, const DjiDroneModel &model, const DjiPayload &payload)
{
    QByteArray out;
    Writer w(&out);
    writeDocumentStart(w);
    w.el(QStringLiteral("author"), QStringLiteral("Sortie"));
    w.el(QStringLiteral("createTime"), QString::number(o.timestampMs));
    w.el(QStringLiteral("updateTime"), QString::number(o.timestampMs));
    writeMissionConfig(w, mission, o, model, payload, true);
    int groupId = 0;
    for (size_t f = 0; f < mission.waylines.size(); ++f)
        writeTemplateFolder(w, *mission.waylines[f].plan, int(f), o, &groupId);
    w.end();
    w.end();
    w.x.writeEndDocument();
    return out;
}

} // namespace sortie::mission::formats::wpml
