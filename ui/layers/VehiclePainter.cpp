#include "VehiclePainter.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

namespace sortie::ui {

namespace {

QPainterPath arrowShape()
{
    QPainterPath path;
    path.moveTo(0, -14);
    path.lineTo(9, 10);
    path.lineTo(0, 5);
    path.lineTo(-9, 10);
    path.closeSubpath();
    return path;
}

} // namespace

QFont VehiclePainter::labelFont()
{
    QFont font;
    font.setPixelSize(11);
    font.setBold(true);
    return font;
}

QSizeF VehiclePainter::labelSize(const QString &label)
{
    const QFontMetricsF metrics(labelFont());
    return QSizeF(metrics.horizontalAdvance(label) + 8, metrics.height() + 2);
}

VehiclePainter::VehiclePainter(QPainter &painter, const MapPalette &colours)
    : m_painter(painter)
    , m_colours(colours)
{
    m_painter.setRenderHint(QPainter::Antialiasing, true);
}

void VehiclePainter::paintHome(const VehicleMark &vehicle, QPointF home)
{
    // The painter's own font, bold at 11 px: the "H" is not a label.
    QFont font = m_painter.font();
    font.setPixelSize(11);
    font.setBold(true);
    m_painter.setFont(font);
    const QRectF square(home - QPointF(7, 7), QSizeF(14, 14));
    m_painter.setPen(QPen(m_colours.outline, 1.5));
    m_painter.setBrush(vehicle.shownColor().darker(120));
    m_painter.drawRect(square);
    m_painter.setPen(m_colours.markText);
    m_painter.drawText(square, Qt::AlignCenter, QStringLiteral("H"));
}

void VehiclePainter::paintArrow(const VehicleMark &vehicle, QPointF at, bool current)
{
    static const QPainterPath arrow = arrowShape();
    m_painter.save();
    m_painter.translate(at);
    if (current) {
        QColor glow = m_colours.attention;
        glow.setAlpha(60);
        m_painter.setPen(QPen(m_colours.attention, 3));
        m_painter.setBrush(glow);
        m_painter.drawEllipse(QPointF(0, 0), 20, 20);
        m_painter.scale(1.2, 1.2);
    }
    m_painter.rotate(vehicle.heading);
    m_painter.setPen(QPen(m_colours.outline, 2.0));
    m_painter.setBrush(vehicle.shownColor());
    m_painter.drawPath(arrow);
    m_painter.restore();
}

void VehiclePainter::paintLabel(const VehicleMark &vehicle, QPointF at, const QRectF &label, bool moved, bool current)
{
    const QColor color = vehicle.shownColor();
    m_painter.setFont(labelFont());
    if (moved) {
        m_painter.setPen(QPen(color, 1));
        m_painter.drawLine(at, QPointF(label.left(), label.center().y()));
    }
    m_painter.setPen(current ? QPen(m_colours.attention, 2) : QPen(color, 1));
    m_painter.setBrush(current ? color : m_colours.labelBox);
    m_painter.drawRoundedRect(label, 3, 3);
    m_painter.setPen(current ? m_colours.markText : color.darker(160));
    m_painter.drawText(label, Qt::AlignCenter, vehicle.label);
}

} // namespace sortie::ui
