#include "DeviationLayer.h"

#include <QPainter>

#include <cmath>

namespace sortie::ui {

DeviationLayer::DeviationLayer(QQuickItem *parent)
    : MapLayer(parent)
{
    m_points.setRoleNames("latitude", "longitude");
    connect(&m_points, &ModelCoordinates::changed, this, [this] {
        readLevels();
        repaint();
        emit modelChanged();
    });
}

void DeviationLayer::setModel(QAbstractItemModel *model)
{
    if (model == m_points.model())
        return;
    m_points.setModel(model);
    readLevels();
    repaint();
    emit modelChanged();
}

void DeviationLayer::readLevels()
{
    m_levels.assign(size_t(m_points.count()), 0);
    QAbstractItemModel *model = m_points.model();
    const int role = m_points.roleId("level");
    if (!model || role < 0)
        return;
    for (int row = 0; row < m_points.count(); ++row)
        m_levels[size_t(row)] = model->index(row, 0).data(role).toInt();
}

QColor DeviationLayer::levelColour(const MapPalette &colours, int level)
{
    switch (level) {
    case 0: return colours.planned;   // green
    case 1: return colours.unplanned; // amber
    default: return colours.noReturn; // red
    }
}

void DeviationLayer::paint(QPainter *painter)
{
    const auto &points = m_points.points();
    if (points.size() < 2)
        return;
    painter->setRenderHint(QPainter::Antialiasing);
    const MapViewport &viewport = paintViewport();
    QPointF previous = viewport.toScreenUnwrapped(points[0]);
    for (size_t i = 1; i < points.size(); ++i) {
        if (std::isnan(points[i].x()) || std::isnan(points[i - 1].x())) {
            previous = viewport.toScreenUnwrapped(points[i]);
            continue;
        }
        const QPointF p = viewport.toScreenUnwrapped(points[i]);
        painter->setPen(QPen(levelColour(colours(), m_levels[i]), 4, Qt::SolidLine, Qt::RoundCap));
        painter->drawLine(previous, p);
        previous = p;
    }
}

} // namespace sortie::ui
