#include "TelemetryPlot.h"

#include "Polyline.h"
#include "TelemetryField.h"
#include "Vehicle.h"

#include <QDateTime>
#include <QPainter>

#include <cmath>
#include <numbers>

namespace sortie::ui {

using vehicle::TelemetryField;

namespace {

const QColor kColours[] = {QColor(0x1e, 0x88, 0xe5), QColor(0xd8, 0x1b, 0x60), QColor(0x43, 0xa0, 0x47), QColor(0xfb, 0x8c, 0x00)};

// Angles are stored in radians: the plot shows degrees, as the instruments do.
bool isAngle(TelemetryField field)
{
    return vehicle::fieldUnit(field) == "rad";
}

} // namespace

TelemetryPlot::TelemetryPlot(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setAntialiasing(true);
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
    if (m_vehicle)
        disconnect(m_vehicle, nullptr, this, nullptr);
    m_vehicle = v;
    if (m_vehicle)
        connect(m_vehicle, &vehicle::Vehicle::telemetryChanged, this, [this] { polish(); update(); });
    polish();
    update();
    emit vehicleChanged();
}

void TelemetryPlot::setFields(const QStringList &fields)
{
    if (fields == m_fields)
        return;
    m_fields = fields;
    polish();
    update();
    emit fieldsChanged();
}

void TelemetryPlot::setWindowSeconds(double seconds)
{
    if (seconds == m_windowSeconds || seconds <= 0)
        return;
    m_windowSeconds = seconds;
    polish();
    update();
    emit windowSecondsChanged();
}

QStringList TelemetryPlot::availableFields()
{
    QStringList names;
    for (size_t i = 0; i < vehicle::kTelemetryFieldCount; ++i)
        names.append(QString::fromLatin1(vehicle::fieldName(TelemetryField(i)).data(), qsizetype(vehicle::fieldName(TelemetryField(i)).size())));
    return names;
}

void TelemetryPlot::updatePolish()
{
    m_series.clear();
    m_sampleCount = 0;
    const QRectF area(48, 8, std::max(1.0, width() - 56), std::max(1.0, height() - 28));
    if (m_vehicle) {
        const auto &history = m_vehicle->history();
        int64_t newest = 0;
        std::vector<std::pair<TelemetryField, QString>> chosen;
        for (const QString &name : std::as_const(m_fields)) {
            const auto field = vehicle::fieldFromName(name.toStdString());
            if (!field)
                continue;
            chosen.emplace_back(*field, name);
            if (const auto last = history.last(*field))
                newest = std::max<int64_t>(newest, last->time);
        }
        // The window, or less while the history is shorter: the data fills the plot from the start.
        int64_t from = newest - int64_t(m_windowSeconds * 1000);
        int64_t oldest = newest;
        for (const auto &[field, name] : chosen) {
            const auto &series = history.series(field);
            if (!series.empty())
                oldest = std::min<int64_t>(oldest, series.at(0).time);
        }
        from = std::max(from, oldest);
        m_spanSeconds = std::max(1.0, double(newest - from) / 1000.0);
        std::vector<vehicle::TelemetrySample> samples;
        for (const auto &[field, name] : chosen) {
            samples.clear();
            history.copyBetween(field, from, newest, samples);
            if (samples.empty())
                continue;
            const double scale = isAngle(field) ? 180.0 / std::numbers::pi : 1.0;
            Series series;
            series.name = name;
            series.unit = isAngle(field) ? QStringLiteral("°") : QString::fromLatin1(vehicle::fieldUnit(field).data());
            series.minimum = series.maximum = samples.front().value * scale;
            for (const auto &s : samples) {
                series.minimum = std::min(series.minimum, s.value * scale);
                series.maximum = std::max(series.maximum, s.value * scale);
            }
            if (series.maximum - series.minimum < 1e-9) {
                series.minimum -= 1;
                series.maximum += 1;
            }
            series.last = samples.back().value * scale;
            QPolygonF points;
            points.reserve(qsizetype(samples.size()));
            for (const auto &s : samples) {
                const double x = area.left() + (double(s.time - from) / (m_spanSeconds * 1000.0)) * area.width();
                const double y = area.bottom() - (s.value * scale - series.minimum) / (series.maximum - series.minimum) * area.height();
                points.append(QPointF(x, y));
            }
            m_sampleCount += int(samples.size());
            series.points = simplifyPolyline(points, 0.5);
            m_series.push_back(std::move(series));
        }
    }
    emit plotted();
}

void TelemetryPlot::paint(QPainter *painter)
{
    const QRectF area(48, 8, std::max(1.0, width() - 56), std::max(1.0, height() - 28));
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
        painter->drawText(area, Qt::AlignCenter, m_vehicle ? tr("No data yet") : tr("Choose a vehicle"));
        return;
    }
    for (size_t i = 0; i < m_series.size(); ++i) {
        const Series &s = m_series[i];
        const QColor colour = kColours[i % std::size(kColours)];
        painter->setPen(QPen(colour, 1.8));
        painter->drawPolyline(s.points);
        painter->drawText(QPointF(area.left() + 6, area.top() + 14 + 14 * double(i)),
                          QStringLiteral("%1 %2 %3 (%4…%5)").arg(s.name).arg(s.last, 0, 'f', 1).arg(s.unit)
                              .arg(s.minimum, 0, 'f', 1).arg(s.maximum, 0, 'f', 1));
    }
    painter->setPen(m_textColor);
    painter->drawText(QRectF(0, area.top(), 44, 14), Qt::AlignRight, QString::number(m_series.front().maximum, 'f', 1));
    painter->drawText(QRectF(0, area.bottom() - 14, 44, 14), Qt::AlignRight, QString::number(m_series.front().minimum, 'f', 1));
}

} // namespace sortie::ui
