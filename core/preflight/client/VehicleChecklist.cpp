#include "VehicleChecklist.h"

#include "PreflightLog.h"
#include "Vehicle.h"

#include <algorithm>

namespace sortie::preflight {

namespace {
QString fixName(double fix)
{
    switch (int(fix)) {
    case 2: return VehicleChecklist::tr("2D fix");
    case 3: return VehicleChecklist::tr("3D fix");
    case 4: return VehicleChecklist::tr("RTK float");
    case 5: return VehicleChecklist::tr("RTK fixed");
    default: return VehicleChecklist::tr("no fix");
    }
}
} // namespace

VehicleChecklist::VehicleChecklist(vehicle::Vehicle *vehicle, Checklist checklist, QString source, QString sourceError,
                                   FactsFunction facts, QObject *parent)
    : QAbstractListModel(parent)
    , m_vehicle(vehicle)
    , m_checklist(std::move(checklist))
    , m_source(std::move(source))
    , m_sourceError(std::move(sourceError))
    , m_facts(std::move(facts))
    , m_ticked(m_checklist.items.size(), false)
    , m_verdicts(m_checklist.items.size())
{
    if (m_vehicle) {
        m_wasArmed = m_vehicle->armed();
        for (auto signal : {&vehicle::Vehicle::telemetryChanged, &vehicle::Vehicle::staleChanged, &vehicle::Vehicle::linkStateChanged,
                            &vehicle::Vehicle::videoStreamUriChanged})
            connect(m_vehicle, signal, this, &VehicleChecklist::refresh);
        connect(m_vehicle, &vehicle::Vehicle::telemetryChanged, this, &VehicleChecklist::watchArming);
    }
    refresh();
}

int VehicleChecklist::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QHash<int, QByteArray> VehicleChecklist::roleNames() const
{
    return {{TitleRole, "title"}, {DetailRole, "detail"}, {OutcomeRole, "outcome"}, {RequiredRole, "required"},
            {ManualRole, "manual"}, {TickedRole, "ticked"}, {HoldsBackRole, "holdsBack"}};
}

QVariant VehicleChecklist::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= count())
        return {};
    const size_t row = size_t(index.row());
    const ChecklistItem &item = m_checklist.items[row];
    const ItemVerdict &verdict = m_verdicts[row];
    switch (role) {
    case Qt::DisplayRole:
    case TitleRole: return titleOf(item);
    case DetailRole: return detailOf(item, verdict);
    case OutcomeRole: return int(verdict.outcome);
    case RequiredRole: return item.required;
    case ManualRole: return item.check == Check::Manual;
    case TickedRole: return bool(m_ticked[row]);
    case HoldsBackRole: return holdsBack(item, verdict, GateArm) || holdsBack(item, verdict, GateAuto);
    default: return {};
    }
}

int VehicleChecklist::passedCount() const
{
    int passed = 0;
    for (const ItemVerdict &v : m_verdicts)
        passed += v.outcome == Outcome::Pass || v.outcome == Outcome::Ticked ? 1 : 0;
    return passed;
}

int VehicleChecklist::holdingCount() const
{
    int holding = 0;
    for (size_t i = 0; i < m_checklist.items.size(); ++i)
        holding += holdsBack(m_checklist.items[i], m_verdicts[i], GateArm) || holdsBack(m_checklist.items[i], m_verdicts[i], GateAuto) ? 1 : 0;
    return holding;
}

bool VehicleChecklist::setTicked(int row, bool ticked)
{
    if (row < 0 || row >= count() || m_checklist.items[size_t(row)].check != Check::Manual)
        return false;
    if (m_ticked[size_t(row)] == ticked)
        return true;
    m_ticked[size_t(row)] = ticked;
    qCInfo(lcPreflight) << (m_vehicle ? m_vehicle->name() : QString()) << (ticked ? "ticked" : "unticked") << titleOf(m_checklist.items[size_t(row)]);
    refresh();
    return true;
}

QStringList VehicleChecklist::blockers(Gate gate) const
{
    QStringList lines;
    for (size_t i = 0; i < m_checklist.items.size(); ++i)
        if (holdsBack(m_checklist.items[i], m_verdicts[i], gate))
            lines.append(tr("%1: %2").arg(titleOf(m_checklist.items[i]), detailOf(m_checklist.items[i], m_verdicts[i])));
    return lines;
}

void VehicleChecklist::refresh()
{
    const PreflightFacts facts = m_vehicle && m_facts ? m_facts(m_vehicle) : PreflightFacts{};
    bool changed = false;
    for (size_t i = 0; i < m_checklist.items.size(); ++i) {
        const ItemVerdict fresh = judge(m_checklist.items[i], facts, m_ticked[i]);
        if (fresh.outcome == m_verdicts[i].outcome && fresh.value == m_verdicts[i].value)
            continue;
        m_verdicts[i] = fresh;
        changed = true;
        const QModelIndex at = index(int(i));
        emit dataChanged(at, at);
    }
    if (changed)
        emit verdictsChanged();
}

void VehicleChecklist::watchArming()
{
    const bool armed = m_vehicle && m_vehicle->armed();
    const bool landed = m_wasArmed && !armed;
    m_wasArmed = armed;
    if (!landed || std::find(m_ticked.begin(), m_ticked.end(), true) == m_ticked.end())
        return;
    qCInfo(lcPreflight) << m_vehicle->name() << "disarmed: the ticks are cleared for the next flight";
    std::fill(m_ticked.begin(), m_ticked.end(), false);
    emit dataChanged(index(0), index(count() - 1), {TickedRole});
    refresh();
}

QString VehicleChecklist::titleOf(const ChecklistItem &item)
{
    if (!item.title.isEmpty())
        return item.title;
    switch (item.check) {
    case Check::Manual: return {};
    case Check::Link: return tr("Link to the vehicle");
    case Check::GpsFix: return tr("GPS fix");
    case Check::Satellites: return tr("Satellites");
    case Check::Battery: return tr("Battery");
    case Check::Home: return tr("Home position");
    case Check::RouteOnBoard: return tr("Route on board");
    case Check::RouteCheck: return tr("Route check");
    case Check::Camera: return tr("Camera");
    }
    return {};
}

QString VehicleChecklist::detailOf(const ChecklistItem &item, const ItemVerdict &verdict)
{
    const bool pass = verdict.outcome == Outcome::Pass;
    switch (verdict.outcome) {
    case Outcome::Ticked: return tr("ticked");
    case Outcome::NotReported: return tr("not reported over this vehicle's link");
    case Outcome::Unticked: return tr("to tick");
    case Outcome::Missing:
        switch (item.check) {
        case Check::RouteOnBoard: return tr("Sortie has uploaded no route to it");
        case Check::RouteCheck: return tr("its route is not the one open");
        default: return tr("not known: no fresh telemetry");
        }
    case Outcome::Pass:
    case Outcome::Fail: break;
    }
    const double value = verdict.value.value_or(0);
    const double minimum = item.minimum.value_or(0);
    switch (item.check) {
    case Check::Manual: return {};
    case Check::Link: return pass ? tr("connected") : tr("no fresh telemetry");
    case Check::GpsFix: return pass ? fixName(value) : tr("%1 (%2 needed)").arg(fixName(value), fixName(minimum));
    case Check::Satellites: return pass ? QString::number(value) : tr("%1 (%2 needed)").arg(value).arg(minimum);
    case Check::Battery:
        return pass ? tr("%1 %").arg(value, 0, 'f', 0) : tr("%1 % (%2 % needed)").arg(value, 0, 'f', 0).arg(minimum, 0, 'f', 0);
    case Check::Home: return pass ? tr("set") : tr("not set");
    case Check::RouteOnBoard: return pass ? tr("the planned route") : tr("differs from the planned route: upload it");
    case Check::RouteCheck: return pass ? tr("no errors") : tr("%n error(s)", nullptr, int(value));
    case Check::Camera: return pass ? tr("stream reported") : tr("no stream reported");
    }
    return {};
}

} // namespace sortie::preflight
