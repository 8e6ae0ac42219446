#include "ElevationProfileView.h"

#include "FollowOwner.h"
#include "LanguageChange.h"
#include "RouteEndurance.h"
#include "TerrainProfileModel.h"
#include "TypedNumber.h"

#include <QItemSelectionModel>
#include <QPainter>
#include <QHoverEvent>
#include <QMouseEvent>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <QCoreApplication>

namespace sortie::ui {

namespace {
constexpr double kLeft = 52, kRight = 10, kTop = 22, kBottom = 20;
const QColor kGround(0x8d, 0x6e, 0x63);
const QColor kGroundFill(0xbc, 0xaa, 0xa4);
const QColor kBand(0xff, 0xb3, 0x00, 90);
const QColor kRoute(0x15, 0x65, 0xc0);
const QColor kSelected(0xff, 0x6f, 0x00);

// Numbers in the language's format, as DisplayUnits writes them ("25,7 m" in German).
QString metres(double v)
{
    return std::isfinite(v) ? QStringLiteral("%1 m").arg(i18n::formatTypedNumber(v, 1)) : QStringLiteral("—");
}

QString distanceText(double m)
{
    return m >= 1000 ? QCoreApplication::translate("ElevationProfileView", "%1 km").arg(i18n::formatTypedNumber(m / 1000, m >= 10000 ? 1 : 2))
                     : QStringLiteral("%1 m").arg(i18n::formatTypedNumber(m, 0));
}
} // namespace

ElevationProfileView::ElevationProfileView(QQuickItem *parent) : QQuickPaintedItem(parent)
{
    setAcceptHoverEvents(true);
    setAcceptedMouseButtons(Qt::LeftButton);
    setAntialiasing(true);
    connect(this, &ElevationProfileView::colorsChanged, this, [this] { update(); });
    connect(this, &ElevationProfileView::markersChanged, this, [this] { update(); });
    connect(this, &ElevationProfileView::readoutChanged, this, &ElevationProfileView::headlineChanged);
    // Painted words are made at each paint: a language change repaints them (and re-words the readout).
    i18n::onLanguageChange(this, [this] {
        if (m_hoverX >= 0)
            hoverAt(m_hoverX);
        emit headlineChanged();
        update();
    });
}

void ElevationProfileView::setModel(TerrainProfileModel *model)
{
    if (model == m_model)
        return;
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    if (model)
        connect(model, &TerrainProfileModel::profileChanged, this, [this] {
            rescale();
            if (m_hoverX >= 0)
                hoverAt(m_hoverX);
            emit headlineChanged();
            update();
        });
    rescale();
    emit modelChanged();
    emit headlineChanged();
    update();
}

void ElevationProfileView::setSelectionModel(QItemSelectionModel *selection)
{
    if (selection == m_selection)
        return;
    if (m_selection)
        disconnect(m_selection, nullptr, this, nullptr);
    m_selection = selection;
    if (selection)
        connect(selection, &QItemSelectionModel::selectionChanged, this, [this] { update(); });
    emit selectionModelChanged();
    update();
}

QRectF ElevationProfileView::plotRect() const
{
    return QRectF(kLeft, kTop, std::max(1.0, width() - kLeft - kRight), std::max(1.0, height() - kTop - kBottom));
}

void ElevationProfileView::geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry)
{
    QQuickPaintedItem::geometryChange(newGeometry, oldGeometry);
    update();
}

void ElevationProfileView::rescale()
{
    double low = std::numeric_limits<double>::infinity(), high = -low;
    if (m_model) {
        const auto &p = m_model->profile();
        const double safe = m_model->route().safeDistance;
        for (size_t i = 0; i < p.size(); ++i) {
            if (p.ground[i].hasValue()) {
                low = std::min(low, p.ground[i].ground);
                high = std::max(high, p.ground[i].ground + safe);
            }
            if (std::isfinite(p.altitudeAmsl[i])) {
                low = std::min(low, p.altitudeAmsl[i]);
                high = std::max(high, p.altitudeAmsl[i]);
            }
        }
    }
    if (!std::isfinite(low)) {
        low = 0;
        high = 100;
    }
    const double span = std::max(20.0, high - low);
    m_low = std::floor((low - 0.08 * span) / 10) * 10;
    m_high = std::ceil((high + 0.12 * span) / 10) * 10;
}

double ElevationProfileView::xOf(double distance) const
{
    const QRectF r = plotRect();
    const double length = m_model ? m_model->length() : 0.0;
    return r.left() + (length > 0 ? distance / length : 0.0) * r.width();
}

double ElevationProfileView::distanceAt(double x) const
{
    const QRectF r = plotRect();
    const double length = m_model ? m_model->length() : 0.0;
    return std::clamp((x - r.left()) / r.width(), 0.0, 1.0) * length;
}

double ElevationProfileView::yOf(double altitude) const
{
    const QRectF r = plotRect();
    return r.bottom() - (altitude - m_low) / (m_high - m_low) * r.height();
}

int ElevationProfileView::legAt(double x) const
{
    const QRectF r = plotRect();
    if (!m_model || m_model->sampleCount() == 0 || x < r.left() - 1 || x > r.right() + 1)
        return -1;
    const auto &vd = m_model->profile().path.vertexDistance;
    const double d = distanceAt(x);
    const auto it = std::upper_bound(vd.begin(), vd.end(), d);
    const int leg = int(it - vd.begin()) - 1;
    return std::clamp(leg, 0, std::max(0, int(vd.size()) - 2));
}

void ElevationProfileView::hoverAt(double x)
{
    m_hoverX = x;
    QString text;
    int leg = -1;
    if (m_model && m_model->sampleCount() > 0 && legAt(x) >= 0) {
        const auto &p = m_model->profile();
        const int i = m_model->sampleAt(distanceAt(x));
        leg = p.path.points[size_t(i)].leg;
        const double ground = p.ground[size_t(i)].hasValue() ? p.ground[size_t(i)].ground : std::nan("");
        text = tr("Leg %1 · %2 · ground %3 · altitude %4 · clearance %5")
                   .arg(leg + 1)
                   .arg(distanceText(p.path.points[size_t(i)].distance), p.ground[size_t(i)].hasValue() ? metres(ground) : tr("no data"),
                        metres(p.altitudeAmsl[size_t(i)]), metres(p.altitudeAmsl[size_t(i)] - ground));
    }
    if (text != m_readout || leg != m_hoveredLeg) {
        m_readout = text;
        m_hoveredLeg = leg;
        emit readoutChanged();
    }
    update();
}

void ElevationProfileView::clickAt(double x)
{
    const int leg = legAt(x);
    if (leg < 0 || !m_model)
        return;
    const int row = m_model->rowOfLeg(leg);
    if (m_selection && m_selection->model() && row >= 0 && row < m_selection->model()->rowCount()) {
        const QModelIndex index = m_selection->model()->index(row, 0);
        m_selection->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    }
    emit legClicked(leg, row);
}

void ElevationProfileView::hoverMoveEvent(QHoverEvent *event)
{
    hoverAt(event->position().x());
}

void ElevationProfileView::hoverLeaveEvent(QHoverEvent *)
{
    m_hoverX = -1;
    if (!m_readout.isEmpty() || m_hoveredLeg != -1) {
        m_readout.clear();
        m_hoveredLeg = -1;
        emit readoutChanged();
    }
    update();
}

void ElevationProfileView::mousePressEvent(QMouseEvent *event)
{
    clickAt(event->position().x());
    event->accept();
}

endurance::RouteEndurance *ElevationProfileView::endurance() const
{
    return m_endurance;
}

void ElevationProfileView::setEndurance(endurance::RouteEndurance *endurance)
{
    if (!followOwner(m_endurance, endurance, this, &endurance::RouteEndurance::estimateChanged, &ElevationProfileView::readMarkers))
        return;
    readMarkers();
    emit enduranceChanged();
}

void ElevationProfileView::readMarkers()
{
    m_markers.clear();
    // By distance, not position: a route that passes a place twice has it twice.
    if (m_endurance && m_endurance->estimate()) {
        const endurance::EnduranceEstimate &estimate = *m_endurance->estimate();
        for (const endurance::BatteryChange &change : estimate.changes)
            m_markers.push_back({change.at.distance, change.planned ? MarkerKind::PlannedChange : MarkerKind::UnplannedChange});
        if (estimate.pointOfNoReturn)
            m_markers.push_back({estimate.pointOfNoReturn->distance, MarkerKind::NoReturn});
    }
    emit markersChanged();
}

double ElevationProfileView::markerDistance(int index) const
{
    if (!m_model || index < 0 || index >= markerCount() || m_model->sampleCount() < 2)
        return qQNaN();
    const double d = m_markers[size_t(index)].distance;
    return std::isfinite(d) ? std::clamp(d, 0.0, m_model->length()) : qQNaN();
}

void ElevationProfileView::setTheme(Theme *theme)
{
    if (theme == m_theme)
        return;
    if (m_theme)
        disconnect(m_theme, nullptr, this, nullptr);
    m_theme = theme;
    if (m_theme)
        connect(m_theme, &Theme::coloursChanged, this, [this] { update(); });
    update();
    emit colorsChanged();
}

void ElevationProfileView::paint(QPainter *painter)
{
    const ThemeColours &colours = coloursOf(m_theme);
    const QColor background = colours.base, textColour = colours.text;
    const QColor kLow = colours.map.exclusion;
    painter->fillRect(QRectF(0, 0, width(), height()), background);
    const QRectF plot = plotRect();
    QFont font = painter->font();
    font.setPixelSize(11);
    painter->setFont(font);
    painter->setPen(textColour);
    if (!m_model || m_model->sampleCount() < 2) {
        painter->drawText(plot, Qt::AlignCenter, m_model && m_model->service() ? tr("Add two waypoints to see the terrain profile")
                                                                               : tr("No terrain source"));
        return;
    }
    const auto &p = m_model->profile();
    const double safe = m_model->route().safeDistance;
    const int columns = std::max(1, int(std::ceil(plot.width())));

    // One summary per pixel column: the highest ground, the lowest altitude, whether data is missing.
    struct Column
    {
        double ground = -std::numeric_limits<double>::infinity();
        double altitude = std::numeric_limits<double>::infinity();
        bool seen = false, hasGround = false, hasAltitude = false, low = false;
    };
    std::vector<Column> col(static_cast<size_t>(columns));
    for (size_t i = 0; i < p.size(); ++i) {
        const int c = std::clamp(int(xOf(p.path.points[i].distance) - plot.left()), 0, columns - 1);
        Column &k = col[size_t(c)];
        k.seen = true;
        if (p.ground[i].hasValue()) {
            k.ground = std::max(k.ground, p.ground[i].ground);
            k.hasGround = true;
        }
        if (std::isfinite(p.altitudeAmsl[i])) {
            k.altitude = std::min(k.altitude, p.altitudeAmsl[i]);
            k.hasAltitude = true;
        }
        if (p.clearance(i) < safe)
            k.low = true;
    }

    // Columns between two samples (fewer samples than pixels) take the line between them; a gap
    // next to a sample without data stays a gap.
    for (int c = 0, last = -1; c < columns; ++c) {
        if (!col[size_t(c)].seen)
            continue;
        if (last >= 0 && c - last > 1) {
            const Column &a = col[size_t(last)], &b = col[size_t(c)];
            for (int g = last + 1; g < c; ++g) {
                const double f = double(g - last) / (c - last);
                Column &k = col[size_t(g)];
                k.hasGround = a.hasGround && b.hasGround;
                k.ground = a.ground + f * (b.ground - a.ground);
                k.hasAltitude = a.hasAltitude && b.hasAltitude;
                k.altitude = a.altitude + f * (b.altitude - a.altitude);
                k.low = a.low && b.low;
            }
        }
        last = c;
    }

    painter->save();
    painter->setClipRect(plot);
    // Ground, as filled runs (a run ends where the data does).
    painter->setPen(Qt::NoPen);
    for (int c = 0; c < columns;) {
        if (!col[size_t(c)].hasGround) {
            ++c;
            continue;
        }
        QPolygonF ground, band;
        const int first = c;
        for (; c < columns && col[size_t(c)].hasGround; ++c) {
            const double x = plot.left() + c + 0.5;
            ground << QPointF(x, yOf(col[size_t(c)].ground));
            band << QPointF(x, yOf(col[size_t(c)].ground + safe));
        }
        QPolygonF fill = ground;
        fill << QPointF(plot.left() + c - 0.5, plot.bottom()) << QPointF(plot.left() + first + 0.5, plot.bottom());
        painter->setBrush(kGroundFill);
        painter->drawPolygon(fill);
        QPolygonF clearance = band;
        for (auto it = ground.crbegin(); it != ground.crend(); ++it)
            clearance << *it;
        painter->setBrush(kBand);
        painter->drawPolygon(clearance);
        painter->setPen(QPen(kGround, 1.5));
        painter->drawPolyline(ground);
        painter->setPen(Qt::NoPen);
    }
    // No data: hatched, never drawn as ground at 0 m.
    for (const auto &s : p.noData) {
        const double x0 = xOf(s.fromDistance), x1 = std::max(xOf(s.toDistance), x0 + 2);
        painter->setBrush(QBrush(colours.map.inactiveEdge, Qt::BDiagPattern));
        painter->drawRect(QRectF(x0, plot.top(), x1 - x0, plot.height()));
    }
    // Too low: a red wash over the stretch (the altitude line is red there too).
    for (const auto &s : p.lowStretches) {
        const double x0 = xOf(s.fromDistance) - 1, x1 = std::max(xOf(s.toDistance) + 1, x0 + 3);
        painter->setBrush(QColor(kLow.red(), kLow.green(), kLow.blue(), 60));
        painter->drawRect(QRectF(x0, plot.top(), x1 - x0, plot.height()));
    }
    // The route's altitude; red where too low.
    painter->setBrush(Qt::NoBrush);
    for (int c = 0; c < columns;) {
        if (!col[size_t(c)].hasAltitude) {
            ++c;
            continue;
        }
        const bool low = col[size_t(c)].low;
        QPolygonF line;
        if (c > 0 && col[size_t(c - 1)].hasAltitude)
            line << QPointF(plot.left() + c - 0.5, yOf(col[size_t(c - 1)].altitude));
        for (; c < columns && col[size_t(c)].hasAltitude && col[size_t(c)].low == low; ++c)
            line << QPointF(plot.left() + c + 0.5, yOf(col[size_t(c)].altitude));
        if (line.size() == 1)
            line << line.first() + QPointF(0.5, 0);
        painter->setPen(QPen(low ? kLow : kRoute, low ? 3.0 : 2.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter->drawPolyline(line);
    }
    // Waypoints: ticks (when they are few enough to tell apart), the selected ones marked.
    std::set<int> selectedRows;
    if (m_selection)
        for (const QModelIndex &i : m_selection->selectedIndexes())
            selectedRows.insert(i.row());
    const auto &wps = m_model->route().waypoints;
    const bool ticks = double(wps.size()) < plot.width() / 4;
    for (size_t k = 0; k < wps.size() && k < p.waypoints.size(); ++k) {
        const bool selected = selectedRows.count(wps[k].row) > 0;
        if (!selected && !ticks)
            continue;
        const double x = xOf(p.path.vertexDistance[k]);
        const double alt = p.waypoints[k].altitudeAmsl;
        if (selected) {
            painter->setPen(QPen(kSelected, 1.5, Qt::DashLine));
            painter->drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        }
        if (std::isfinite(alt)) {
            painter->setPen(QPen(selected ? kSelected : kRoute, 1.5));
            painter->setBrush(selected ? kSelected : background);
            painter->drawEllipse(QPointF(x, yOf(alt)), selected ? 5.0 : 3.0, selected ? 5.0 : 3.0);
        }
    }
    // Markers: a line in their colour and their label, where the path passes closest to them.
    for (int i = 0; i < markerCount(); ++i) {
        const double d = markerDistance(i);
        if (!std::isfinite(d))
            continue;
        // The map's colours for the same marks (EnduranceLayer).
        const MarkerKind kind = m_markers[size_t(i)].kind;
        const QColor colour = kind == MarkerKind::PlannedChange ? colours.map.planned
                            : kind == MarkerKind::UnplannedChange ? colours.map.unplanned
                                                                  : colours.map.noReturn;
        const double x = xOf(d);
        painter->setPen(QPen(colour, 2));
        painter->drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        const QString label = kind == MarkerKind::NoReturn ? tr("no return") : tr("battery change");
        const QFontMetricsF metrics(font);
        const double w = metrics.horizontalAdvance(label) + 6;
        const QRectF box(std::min(x + 3, plot.right() - w), plot.top() + 3 + 15 * (i % 2), w, metrics.height());
        painter->fillRect(box, background);
        painter->drawText(box, Qt::AlignCenter, label);
    }
    // Hover: a cursor line.
    if (m_hoverX >= plot.left() && m_hoverX <= plot.right()) {
        painter->setPen(QPen(textColour, 1, Qt::DotLine));
        painter->drawLine(QPointF(m_hoverX, plot.top()), QPointF(m_hoverX, plot.bottom()));
    }
    painter->restore();

    // Frame, axes and labels.
    painter->setPen(QPen(colours.map.terrain, 1));
    painter->setBrush(Qt::NoBrush);
    painter->drawRect(plot);
    painter->setPen(textColour);
    const QFontMetricsF fm(font);
    for (double a : {m_low, (m_low + m_high) / 2, m_high}) {
        const QString label = QStringLiteral("%1 m").arg(i18n::formatTypedNumber(a, 0));
        painter->drawText(QRectF(0, yOf(a) - fm.height() / 2, kLeft - 6, fm.height()), Qt::AlignRight | Qt::AlignVCenter, label);
    }
    painter->drawText(QRectF(plot.left(), plot.bottom() + 2, 120, kBottom - 2), Qt::AlignLeft | Qt::AlignTop, QStringLiteral("0"));
    painter->drawText(QRectF(plot.right() - 120, plot.bottom() + 2, 120, kBottom - 2), Qt::AlignRight | Qt::AlignTop,
                      distanceText(m_model->length()));
    const QString title = tr("Ground: %1").arg(m_model->sourceText());
    const QString right = headline();
    const double rightWidth = std::min(fm.horizontalAdvance(right) + 4, width() - kLeft - kRight);
    painter->drawText(QRectF(kLeft, 2, std::max(0.0, width() - kLeft - kRight - rightWidth - 12), kTop - 4),
                      Qt::AlignLeft | Qt::AlignVCenter, fm.elidedText(title, Qt::ElideRight, std::max(0.0, width() - kLeft - kRight - rightWidth - 12)));
    painter->setPen(m_readout.isEmpty() && p.minClearance && p.minClearance->clearance < safe ? kLow : textColour);
    painter->drawText(QRectF(width() - kRight - rightWidth, 2, rightWidth, kTop - 4), Qt::AlignRight | Qt::AlignVCenter,
                      fm.elidedText(right, Qt::ElideLeft, rightWidth));
}

QString ElevationProfileView::headline() const
{
    if (!m_readout.isEmpty())
        return m_readout;
    if (!m_model || m_model->sampleCount() < 2)
        return {};
    const auto &p = m_model->profile();
    return p.minClearance ? tr("lowest clearance %1").arg(metres(p.minClearance->clearance)) : tr("clearance unknown");
}

} // namespace sortie::ui
