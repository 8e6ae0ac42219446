#include "ZoneProfileOverlay.h"

#include "Airspace.h"
#include "ElevationProfileView.h"
#include "FollowOwner.h"
#include "ZoneColours.h"

#include <QFontMetricsF>
#include <QPainter>

#include <cmath>

namespace sortie::ui {

namespace {
constexpr int kSteps = 24;  // points along each of the band's edges (AGL limits follow the ground)
}

ZoneProfileOverlay::ZoneProfileOverlay(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setAcceptedMouseButtons(Qt::NoButton); // the profile under it takes hover and clicks
}

void ZoneProfileOverlay::setView(ElevationProfileView *view)
{
    if (view == m_view)
        return;
    if (m_view)
        disconnect(m_view, nullptr, this, nullptr);
    m_view = view;
    if (m_view) {
        connect(m_view, &ElevationProfileView::modelChanged, this, &ZoneProfileOverlay::followModel);
        followModel();
    }
    update();
    emit viewChanged();
}

void ZoneProfileOverlay::followModel()
{
    disconnect(m_profile);
    if (m_view && m_view->model())
        m_profile = connect(m_view->model(), &TerrainProfileModel::profileChanged, this, [this] { update(); });
    update();
}

airspace::Airspace *ZoneProfileOverlay::airspace() const
{
    return m_airspace;
}

void ZoneProfileOverlay::setAirspace(airspace::Airspace *airspace)
{
    if (!followOwner(m_airspace, airspace, this, &airspace::Airspace::crossingsChanged, [this] { update(); }))
        return;
    update();
    emit airspaceChanged();
}

QPolygonF ZoneProfileOverlay::bandOf(const airspace::ZoneCrossing &c) const
{
    const TerrainProfileModel *model = m_view ? m_view->model() : nullptr;
    if (!model || model->sampleCount() < 2)
        return {};
    const terrain::TerrainProfile &profile = model->profile();
    const QRectF plot = m_view->plotArea();
    const double from = c.from, to = c.to;
    const auto groundAt = [&](double d) {
        const int i = model->sampleAt(d);
        return i >= 0 && profile.ground[size_t(i)].hasValue() ? profile.ground[size_t(i)].ground : qQNaN();
    };
    // A limit's y at a distance; NaN where its reference's ground is unknown.
    const auto yOf = [&](const std::optional<airspace::HeightLimit> &limit, double d, bool ceiling) {
        if (!limit) {
            if (ceiling)
                return plot.top();
            const double g = groundAt(d);
            return std::isfinite(g) ? m_view->yOf(g) : plot.bottom();
        }
        const double base = limit->reference == airspace::HeightReference::AboveTerrain ? groundAt(d)
                          : limit->reference == airspace::HeightReference::AboveHome
                              ? (profile.homeGround.hasValue() ? profile.homeGround.ground : qQNaN())
                              : 0.0;
        return std::isfinite(base) ? std::clamp(m_view->yOf(base + limit->metres), plot.top(), plot.bottom()) : qQNaN();
    };
    QPolygonF top, bottom;
    for (int i = 0; i <= kSteps; ++i) {
        const double d = from + (to - from) * i / kSteps;
        const double x = m_view->xOf(d);
        const double yTop = yOf(c.ceiling, d, true);
        const double yBottom = yOf(c.floor, d, false);
        if (!std::isfinite(yTop) || !std::isfinite(yBottom))
            return {};  // a limit that cannot be placed is not drawn at a made-up height
        top << QPointF(x, yTop);
        bottom.prepend(QPointF(x, yBottom));
    }
    return top + bottom;
}

QRectF ZoneProfileOverlay::bandRect(int index) const
{
    if (!m_airspace || index < 0 || index >= m_airspace->crossingCount())
        return {};
    return bandOf(m_airspace->crossings()[size_t(index)]).boundingRect();
}

void ZoneProfileOverlay::paint(QPainter *painter)
{
    QPainter &p = *painter;
    m_bands = 0;
    if (!m_view || !m_airspace) {
        emit painted();
        return;
    }
    p.setRenderHint(QPainter::Antialiasing);
    p.setClipRect(m_view->plotArea());
    QFont font = p.font();
    font.setPixelSize(11);
    p.setFont(font);
    const QFontMetricsF metrics(font);
    double lastLabelEnd = -1e9;
    for (const airspace::ZoneCrossing &c : m_airspace->crossings()) {
        const QPolygonF band = bandOf(c);
        if (band.isEmpty())
            continue;
        ++m_bands;
        const bool exclusion = c.kind == airspace::ZoneKind::Exclusion;
        const MapPalette &palette = coloursOf(m_view ? m_view->theme() : nullptr).map;
        const QColor colour = zoneColour(palette, c.kind, c.restriction);
        QColor wash = colour;
        wash.setAlpha(40);
        p.setPen(Qt::NoPen);
        p.setBrush(wash);
        p.drawPolygon(band);
        p.setBrush(keepsOut(c.kind, c.restriction) ? QBrush(colour, Qt::BDiagPattern) : exclusion ? QBrush(Qt::NoBrush) : QBrush(colour, Qt::FDiagPattern));
        p.setPen(QPen(colour, 1.5));
        p.drawPolygon(band);
        // The name over the band, unless the band before took that place.
        const QRectF box = band.boundingRect();
        const QString &name = c.name;
        const double w = metrics.horizontalAdvance(name);
        const QPointF at(box.left() + 2, box.top() + metrics.ascent() + 2);
        if (at.x() > lastLabelEnd + 4 && w + 4 <= std::max(box.width(), 60.0)) {
            p.setPen(colour.darker(140));
            p.drawText(at, name);
            lastLabelEnd = at.x() + w;
        }
    }
    emit painted();
}

} // namespace sortie::ui
