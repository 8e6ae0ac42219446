#include "TelemetryPlot.h"

#include "LanguageChange.h"
#include "Polyline.h"
#include "TelemetryFieldNames.h"
#include "TypedNumber.h"
#include "TelemetryField.h"
#include "Vehicle.h"
#include "VehiclePalette.h"

#include <QDateTime>
#include <QPainter>

#include <cmath>

namespace sortie::ui {

using vehicle::TelemetryField;

namespace {

const QColor kColours[] = {QColor(0x1e, 0x88, 0xe5), QColor(0xd8, 0x1b, 0x60), QColor(0x43, 0xa0, 0x47),
                           QColor(0xfb, 0x8c, 0x00), QColor(0x8e, 0x24, 0xaa), QColor(0x00, 0x89, 0x7b)};
constexpr double kAxisWidth = 48;

QString unitOf(TelemetryField field)
{
    if (vehicle::isAngle(field))
        return QStringLiteral("°");
    const auto unit = vehicle::fieldUnit(field);
    return QString::fromLatin1(unit.data(), qsizetype(unit.size()));
}

} // namespace

TelemetryPlot::TelemetryPlot(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setAntialiasing(true);
    // The legend, the axes' words and the field names are made when laid out: made again.
    i18n::onLanguageChange(this, [this] {
        emit fieldTitlesChanged();
        redraw();
    });
}

void TelemetryPlot::redraw()
{
    if (!isVisible())
        return; // a hidden plot (a page not shown) would still cost the window a frame: drawn when shown
    polish();
    update();
}

void TelemetryPlot::itemChange(ItemChange change, const ItemChangeData &value)
{
    QQuickPaintedItem::itemChange(change, value);
    if (change == ItemVisibleHasChanged)
        redraw();
}

QObject *TelemetryPlot::vehicle() const
{
    return m_vehicle.data();
}

void TelemetryPlot::setVehicle(QObject *object)
{
    auto *v = qobject_cast<vehicle::Vehicle *>(object);
    if (v == m_vehicle)
        return;
    m_vehicle = v;
    watch();
    emit vehicleChanged();
}

void TelemetryPlot::setFleet(QAbstractItemModel *fleet)
{
    if (fleet == m_fleet)
        return;
    if (m_fleet)
        disconnect(m_fleet, nullptr, this, nullptr);
    m_fleet = fleet;
    if (m_fleet) {
        connect(m_fleet, &QAbstractItemModel::rowsInserted, this, &TelemetryPlot::watch);
        connect(m_fleet, &QAbstractItemModel::rowsRemoved, this, &TelemetryPlot::watch);
        connect(m_fleet, &QAbstractItemModel::modelReset, this, &TelemetryPlot::watch);
    }
    watch();
    emit vehicleChanged();
}

void TelemetryPlot::setCompare(bool compare)
{
    if (compare == m_compare)
        return;
    m_compare = compare;
    watch();
    emit vehicleChanged();
}

std::vector<std::pair<vehicle::Vehicle *, int>> TelemetryPlot::sources() const
{
    std::vector<std::pair<vehicle::Vehicle *, int>> out;
    if (m_compare && m_fleet) {
        int role = -1;
        const auto names = m_fleet->roleNames();
        for (auto it = names.cbegin(); it != names.cend(); ++it)
            if (it.value() == "vehicle")
                role = it.key();
        for (int row = 0; role >= 0 && row < m_fleet->rowCount(); ++row)
            if (auto *v = qobject_cast<vehicle::Vehicle *>(m_fleet->index(row, 0).data(role).value<QObject *>()))
                out.emplace_back(v, row);
    } else if (m_vehicle) {
        out.emplace_back(m_vehicle.data(), -1);
    }
    return out;
}

// Redraws whenever any plotted vehicle reports.
void TelemetryPlot::watch()
{
    for (const auto &v : m_watched)
        if (v)
            disconnect(v, nullptr, this, nullptr);
    m_watched.clear();
    for (const auto &[v, row] : sources()) {
        m_watched.emplace_back(v);
        connect(v, &vehicle::Vehicle::historyChanged, this, &TelemetryPlot::redraw); // its time axis moves with every sample
    }
    redraw();
}

void TelemetryPlot::setFields(const QStringList &fields)
{
    if (fields == m_fields)
        return;
    m_fields = fields;
    redraw();
    emit fieldsChanged();
}

void TelemetryPlot::setWindowSeconds(double seconds)
{
    if (seconds == m_windowSeconds || seconds <= 0)
        return;
    m_windowSeconds = seconds;
    redraw();
    emit windowSecondsChanged();
}

QStringList TelemetryPlot::availableFields()
{
    QStringList names;
    for (size_t i = 0; i < vehicle::kTelemetryFieldCount; ++i)
        names.append(QString::fromLatin1(vehicle::fieldName(TelemetryField(i)).data(), qsizetype(vehicle::fieldName(TelemetryField(i)).size())));
    return names;
}

QStringList TelemetryPlot::fieldTitles()
{
    QStringList titles;
    for (size_t i = 0; i < vehicle::kTelemetryFieldCount; ++i)
        titles.append(telemetryFieldTitle(TelemetryField(i)));
    return titles;
}

QString TelemetryPlot::seriesLabel(int i) const
{
    return i >= 0 && i < seriesCount() ? m_series[size_t(i)].label : QString();
}

QColor TelemetryPlot::seriesColor(int i) const
{
    return i >= 0 && i < seriesCount() ? m_series[size_t(i)].colour : QColor();
}

int TelemetryPlot::seriesAxis(int i) const
{
    return i >= 0 && i < seriesCount() ? m_series[size_t(i)].group : -1;
}

QRectF TelemetryPlot::plotArea() const
{
    const double right = m_groups.size() > 1 ? kAxisWidth : 8;
    return QRectF(kAxisWidth, 8, std::max(1.0, width() - kAxisWidth - right), std::max(1.0, height() - 28));
}

void TelemetryPlot::updatePolish()
{
    m_series.clear();
    m_groups.clear();
    m_sampleCount = 0;
    std::vector<std::pair<TelemetryField, QString>> chosen;
    for (const QString &name : std::as_const(m_fields))
        if (const auto field = vehicle::fieldFromName(name.toStdString()))
            chosen.emplace_back(*field, telemetryFieldTitle(*field));
    const auto vehicles = sources();
    // One time span for all: the window before the newest sample, or less while the histories are shorter.
    int64_t newest = 0;
    for (const auto &[v, row] : vehicles)
        for (const auto &[field, name] : chosen)
            if (const auto last = v->history().last(field))
                newest = std::max<int64_t>(newest, last->time);
    int64_t oldest = newest;
    for (const auto &[v, row] : vehicles)
        for (const auto &[field, name] : chosen)
            if (!v->history().series(field).empty())
                oldest = std::min<int64_t>(oldest, v->history().series(field).at(0).time);
    const int64_t from = std::max(newest - int64_t(m_windowSeconds * 1000), oldest);
    m_spanSeconds = std::max(1.0, double(newest - from) / 1000.0);

    std::vector<vehicle::TelemetrySample> samples;
    for (const auto &[v, row] : vehicles) {
        for (const auto &[field, name] : chosen) {
            samples.clear();
            v->history().copyBetween(field, from, newest, samples);
            if (samples.empty())
                continue;
            const QString unit = unitOf(field);
            Series series;
            series.label = vehicles.size() > 1 || m_compare ? QStringLiteral("%1 %2").arg(v->name(), name) : name;
            series.colour = row >= 0 && chosen.size() == 1 ? client::vehicleColor(row) : kColours[m_series.size() % std::size(kColours)];
            auto group = std::find_if(m_groups.begin(), m_groups.end(), [&](const Group &g) { return g.unit == unit; });
            if (group == m_groups.end()) {
                m_groups.push_back({unit, series.colour, samples.front().value, samples.front().value});
                group = m_groups.end() - 1;
            }
            series.group = int(group - m_groups.begin());
            series.raw.reserve(samples.size());
            for (const auto &s : samples) {
                const double value = s.value;
                group->minimum = std::min(group->minimum, value);
                group->maximum = std::max(group->maximum, value);
                series.raw.emplace_back(double(s.time - from), value);
            }
            series.last = series.raw.back().y();
            m_sampleCount += int(samples.size());
            m_series.push_back(std::move(series));
        }
    }
    for (Group &g : m_groups) {
        if (g.maximum - g.minimum < 1e-9) {
            g.minimum -= 1;
            g.maximum += 1;
        }
    }
    const QRectF area = plotArea();
    for (Series &series : m_series) {
        const Group &g = m_groups[size_t(series.group)];
        QPolygonF points;
        points.reserve(qsizetype(series.raw.size()));
        for (const QPointF &p : series.raw)
            points.append(QPointF(area.left() + p.x() / (m_spanSeconds * 1000.0) * area.width(),
                                  area.bottom() - (p.y() - g.minimum) / (g.maximum - g.minimum) * area.height()));
        series.points = simplifyPolyline(points, 0.5);
        series.raw.clear();
        series.raw.shrink_to_fit();
    }
    emit plotted();
}

void TelemetryPlot::paint(QPainter *painter)
{
    const QRectF area = plotArea();
    painter->setRenderHint(QPainter::Antialiasing);
    QColor grid = m_textColor;
    grid.setAlpha(50);
    painter->setPen(QPen(grid, 1));
    painter->drawRect(area);
    for (int i = 1; i < 4; ++i)
        painter->drawLine(QPointF(area.left(), area.top() + area.height() * i / 4), QPointF(area.right(), area.top() + area.height() * i / 4));
    QFont font = painter->font();
    font.setPixelSize(11);
    painter->setFont(font);
    painter->setPen(m_textColor);
    painter->drawText(QRectF(area.left(), area.bottom() + 2, area.width(), 16), Qt::AlignLeft,
                      tr("−%1 s").arg(m_spanSeconds, 0, 'f', 0));
    painter->drawText(QRectF(area.left(), area.bottom() + 2, area.width(), 16), Qt::AlignRight, tr("now"));
    if (m_series.empty()) {
        const bool any = m_compare ? m_fleet && m_fleet->rowCount() > 0 : bool(m_vehicle);
        painter->drawText(area, Qt::AlignCenter, any ? tr("No data yet") : tr("Choose a vehicle"));
        return;
    }
    const QFontMetricsF metrics(font);
    for (size_t i = 0; i < m_series.size(); ++i) {
        const Series &s = m_series[i];
        painter->setPen(QPen(s.colour, 1.8));
        painter->drawPolyline(s.points);
        const Group &g = m_groups[size_t(s.group)];
        QString legend = QStringLiteral("%1 %2 %3").arg(s.label, i18n::formatTypedNumber(s.last, 1), g.unit).trimmed();
        if (s.group >= 2) // no axis of its own: its range in the legend
            legend += QStringLiteral(" (%1…%2)").arg(i18n::formatTypedNumber(g.minimum, 1), i18n::formatTypedNumber(g.maximum, 1));
        painter->drawText(QPointF(area.left() + 6, area.top() + 14 + 14 * double(i)),
                          metrics.elidedText(legend, Qt::ElideRight, area.width() - 12));
    }
    // Axes: the first unit on the left, the second on the right, each in its first series' colour.
    for (size_t i = 0; i < m_groups.size() && i < 2; ++i) {
        const Group &g = m_groups[i];
        const bool left = i == 0;
        const QRectF column = left ? QRectF(0, 0, kAxisWidth - 4, 14) : QRectF(area.right() + 4, 0, kAxisWidth - 4, 14);
        const Qt::Alignment align = left ? Qt::AlignRight : Qt::AlignLeft;
        painter->setPen(m_groups.size() > 1 ? g.colour : m_textColor);
        painter->drawText(column.translated(0, area.top()), align, i18n::formatTypedNumber(g.maximum, 1));
        painter->drawText(column.translated(0, area.center().y() - 7), align, g.unit);
        painter->drawText(column.translated(0, area.bottom() - 14), align, i18n::formatTypedNumber(g.minimum, 1));
    }
}

} // namespace sortie::ui
