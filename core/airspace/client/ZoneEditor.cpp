#include "ZoneEditor.h"
#include "TypedNumber.h"

#include "AddZoneCommand.h"
#include "Airspace.h"
#include "EditZoneCommand.h"
#include "RemoveZoneCommand.h"

#include <cmath>
#include <QCoreApplication>

namespace sortie::airspace {

namespace {
std::vector<GeoPoint> *outerRing(Zone &z)
{
    auto *polygons = std::get_if<ZonePolygons>(&z.shape);
    return polygons && !polygons->parts.empty() && !polygons->parts.front().rings.empty() ? &polygons->parts.front().rings.front() : nullptr;
}

GeoPoint pointOf(const QGeoCoordinate &c)
{
    return {c.latitude(), c.longitude()};
}

std::optional<double> metresOf(const QVariant &v, bool *bad)
{
    if (!v.isValid() || v.isNull() || (v.typeId() == QMetaType::QString && v.toString().trimmed().isEmpty()))
        return std::nullopt;
    bool ok = false;
    double m = 0;
    if (v.typeId() == QMetaType::QString) {  // as typed: "12,5" in German, or with a dot
        const std::optional<double> typed = i18n::parseTypedNumber(v.toString());
        ok = typed.has_value();
        m = typed.value_or(0);
    } else {
        m = v.toDouble(&ok);
    }
    if (!ok) {
        *bad = true;
        return std::nullopt;
    }
    if (std::isnan(m))
        return std::nullopt;
    if (!std::isfinite(m))
        *bad = true;
    return m;
}
} // namespace

ZoneEditor::ZoneEditor(Airspace *store)
    : QObject(store), m_store(store)
{
    connect(&m_stack, &QUndoStack::indexChanged, this, &ZoneEditor::stackChanged);
    connect(store, &Airspace::changed, this, &ZoneEditor::figureChanged);
    connect(store, &Airspace::selectedZoneChanged, this, &ZoneEditor::figureChanged);
}

QVariantList ZoneEditor::figure() const
{
    const int i = m_store->selectedCustom();
    if (i < 0)
        return {};
    Zone z = m_store->customZones()[size_t(i)];
    QVariantList out;
    if (const auto *ring = outerRing(z))
        for (const GeoPoint &p : *ring)
            out.append(QVariant::fromValue(QGeoCoordinate(p.latitude, p.longitude)));
    else if (const auto *circle = std::get_if<ZoneCircle>(&z.shape))
        out.append(QVariant::fromValue(QGeoCoordinate(circle->center.latitude, circle->center.longitude)));
    return out;
}

double ZoneEditor::radius() const
{
    const int i = m_store->selectedCustom();
    if (i < 0)
        return 0.0;
    const auto *circle = std::get_if<ZoneCircle>(&m_store->customZones()[size_t(i)].shape);
    return circle ? circle->radius : 0.0;
}

ZoneFields ZoneEditor::fields() const
{
    const int i = m_store->selectedCustom();
    if (i < 0)
        return {};
    const Zone &z = m_store->customZones()[size_t(i)];
    const auto metres = [](const std::optional<HeightLimit> &l) { return l ? QString::number(l->metres, 'g', 10) : QString(); };
    const std::optional<HeightLimit> &limit = z.floor ? z.floor : z.ceiling;
    const HeightReference r = limit ? limit->reference : HeightReference::Amsl;
    ZoneFields f;
    f.chosen = true;
    f.name = z.name;
    f.inclusion = z.kind == ZoneKind::Inclusion;
    f.floor = metres(z.floor);
    f.ceiling = metres(z.ceiling);
    f.reference = r == HeightReference::Amsl ? QStringLiteral("AMSL") : r == HeightReference::AboveTerrain ? QStringLiteral("AGL") : QStringLiteral("HOME");
    return f;
}

int ZoneEditor::addPolygon(const QList<QGeoCoordinate> &corners)
{
    if (corners.size() < 3)
        {
        refuse(tr("A zone needs at least three corners."));
        return -1;
    }
    ZonePolygon polygon;
    polygon.rings.emplace_back();
    for (const QGeoCoordinate &c : corners)
        polygon.rings.front().push_back(pointOf(c));
    Zone z;
    z.name = nextName();
    z.shape = ZonePolygons{{polygon}};
    z.source = ZoneSource::ServerCustom;
    z.origin = QCoreApplication::translate("ZoneEditor", "drawn on the map");
    if (const QString problem = shapeProblem(z); !problem.isEmpty())
        {
        refuse(tr("This polygon cannot be a zone: %1").arg(problem));
        return -1;
    }
    return add(std::move(z), tr("Draw zone"));
}

int ZoneEditor::addCircle(const QGeoCoordinate &centre, double radius)
{
    if (!centre.isValid() || !(radius > 0) || !std::isfinite(radius))
        {
        refuse(tr("A circular zone needs a centre and a radius above 0 m."));
        return -1;
    }
    Zone z;
    z.name = nextName();
    z.shape = ZoneCircle{pointOf(centre), radius};
    z.source = ZoneSource::ServerCustom;
    z.origin = QCoreApplication::translate("ZoneEditor", "drawn on the map");
    return add(std::move(z), tr("Draw circular zone"));
}

bool ZoneEditor::removeZone(int zone)
{
    return removeZoneAs(zone, tr("Remove zone"));
}

bool ZoneEditor::removeZoneAs(int zone, const QString &text)
{
    if (zone < 0 || zone >= int(m_store->customZones().size()))
        return refuse(tr("There is no drawn zone %1.").arg(zone + 1));
    m_stack.push(new RemoveZoneCommand(m_store, zone, m_store->customZones()[size_t(zone)], text));
    return true;
}

bool ZoneEditor::moveVertex(int zone, int vertex, const QGeoCoordinate &to, mission::EditStep step)
{
    if (!to.isValid())
        return refuse(tr("That is not a position."));
    return edit(zone, [&](Zone &z) {
        if (auto *circle = std::get_if<ZoneCircle>(&z.shape)) {
            if (vertex != 0)
                return refuse(tr("A circle has only its centre to move."));
            circle->center = pointOf(to);
            return true;
        }
        auto *ring = outerRing(z);
        if (!ring || vertex < 0 || vertex >= int(ring->size()))
            return refuse(tr("The zone has no corner %1.").arg(vertex + 1));
        (*ring)[size_t(vertex)] = pointOf(to);
        return true;
    }, tr("Move zone corner"), QCoreApplication::translate("ZoneEditor", "vertex %1").arg(vertex), step);
}

bool ZoneEditor::insertVertex(int zone, int vertex, const QGeoCoordinate &at)
{
    if (!at.isValid())
        return refuse(tr("That is not a position."));
    return edit(zone, [&](Zone &z) {
        auto *ring = outerRing(z);
        if (!ring || vertex < 0 || vertex > int(ring->size()))
            return refuse(tr("A corner can be added only to a polygon, on one of its edges."));
        ring->insert(ring->begin() + vertex, pointOf(at));
        return true;
    }, tr("Add zone corner"), QStringLiteral("insert"));
}

bool ZoneEditor::removeVertex(int zone, int vertex)
{
    return edit(zone, [&](Zone &z) {
        auto *ring = outerRing(z);
        if (!ring || vertex < 0 || vertex >= int(ring->size()))
            return refuse(tr("The zone has no corner %1.").arg(vertex + 1));
        if (ring->size() <= 3)
            return refuse(tr("A zone keeps at least three corners."));
        ring->erase(ring->begin() + vertex);
        return true;
    }, tr("Remove zone corner"), QStringLiteral("remove"));
}

bool ZoneEditor::setRadius(int zone, double metres, mission::EditStep step)
{
    if (!(metres > 0) || !std::isfinite(metres))
        return refuse(tr("The radius must be above 0 m."));
    return edit(zone, [&](Zone &z) {
        auto *circle = std::get_if<ZoneCircle>(&z.shape);
        if (!circle)
            return refuse(tr("Only a circular zone has a radius."));
        circle->radius = metres;
        return true;
    }, tr("Zone radius"), QStringLiteral("radius"), step);
}

bool ZoneEditor::setName(int zone, const QString &name)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty())
        return refuse(tr("A zone needs a name."));
    return edit(zone, [&](Zone &z) { z.name = trimmed; return true; }, tr("Rename zone"), QStringLiteral("name"));
}

bool ZoneEditor::setKind(int zone, const QString &kind)
{
    if (kind != QLatin1String("exclusion") && kind != QLatin1String("inclusion"))
        return refuse(tr("A zone is an exclusion or an inclusion zone, not \"%1\".").arg(kind));
    return edit(zone, [&](Zone &z) {
        z.kind = kind == QLatin1String("exclusion") ? ZoneKind::Exclusion : ZoneKind::Inclusion;
        return true;
    }, tr("Zone kind"), QStringLiteral("kind"));
}

bool ZoneEditor::setLimits(int zone, const QVariant &floor, const QVariant &ceiling, const QString &reference)
{
    HeightReference r;
    if (reference == QLatin1String("AMSL"))
        r = HeightReference::Amsl;
    else if (reference == QLatin1String("AGL"))
        r = HeightReference::AboveTerrain;
    else if (reference == QLatin1String("HOME"))
        r = HeightReference::AboveHome;
    else
        return refuse(tr("Heights are AMSL, AGL or HOME, not \"%1\".").arg(reference));
    bool bad = false;
    const std::optional<double> low = metresOf(floor, &bad), high = metresOf(ceiling, &bad);
    if (bad)
        return refuse(tr("A floor or ceiling is a number of metres, or empty."));
    if (low && high && *high <= *low)
        return refuse(tr("The ceiling (%1 m) must be above the floor (%2 m).").arg(*high).arg(*low));
    return edit(zone, [&](Zone &z) {
        z.floor = low ? std::optional<HeightLimit>(HeightLimit{*low, r}) : std::nullopt;
        z.ceiling = high ? std::optional<HeightLimit>(HeightLimit{*high, r}) : std::nullopt;
        return true;
    }, tr("Zone floor and ceiling"), QStringLiteral("limits"));
}

bool ZoneEditor::edit(int zone, const std::function<bool(Zone &)> &change, const QString &text, const QString &kind, mission::EditStep step)
{
    if (zone < 0 || zone >= int(m_store->customZones().size()))
        return refuse(tr("There is no drawn zone %1.").arg(zone + 1));
    const Zone before = m_store->customZones()[size_t(zone)];
    Zone after = before;
    if (!change(after))
        return false;
    if (std::holds_alternative<ZonePolygons>(after.shape))
        if (const QString problem = shapeProblem(after); !problem.isEmpty())
            return refuse(tr("The zone would not be a valid polygon: %1").arg(problem));
    // Continuing steps carry the gesture; so does the Done step that ends an open gesture.
    const int merge = (step == mission::EditStep::Continuing || m_gestureOpen) ? m_gesture : 0;
    if (step == mission::EditStep::Done) {
        ++m_gesture;
        m_gestureOpen = false;
    } else {
        m_gestureOpen = true;
    }
    if (after == before)
        return true;
    m_stack.push(new EditZoneCommand(m_store, zone, before, std::move(after), text, kind, merge));
    return true;
}

int ZoneEditor::add(Zone zone, const QString &text)
{
    const int index = int(m_store->customZones().size());
    m_stack.push(new AddZoneCommand(m_store, index, std::move(zone), text));
    return index;
}

bool ZoneEditor::refuse(const QString &reason)
{
    emit refused(reason);
    return false;
}

QString ZoneEditor::nextName() const
{
    int n = 1;
    const auto taken = [&](const QString &name) {
        for (const Zone &z : m_store->customZones())
            if (z.name == name)
                return true;
        return false;
    };
    while (taken(tr("Zone %1").arg(n)))
        ++n;
    return tr("Zone %1").arg(n);
}

} // namespace sortie::airspace
