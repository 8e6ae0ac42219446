#include "MapScaleBar.h"

#include "LanguageChange.h"
#include "MapView.h"

#include <QPainter>

namespace sortie::ui {

MapScaleBar::MapScaleBar(QQuickItem *parent)
    : QQuickPaintedItem(parent)
{
    setImplicitSize(140, 26);
    setAntialiasing(true);
    i18n::onLanguageChange(this, [this] { recompute(); }); // its label ("1 km") is worded then
}

void MapScaleBar::setMap(MapView *map)
{
    if (map == m_map)
        return;
    if (m_map)
        disconnect(m_map, nullptr, this, nullptr);
    m_map = map;
    if (m_map)
        connect(m_map, &MapView::viewportChanged, this, &MapScaleBar::recompute);
    recompute();
    emit mapChanged();
}

void MapScaleBar::setImperial(bool imperial)
{
    if (imperial == m_imperial)
        return;
    m_imperial = imperial;
    recompute();
}

void MapScaleBar::setColor(const QColor &color)
{
    if (color == m_color)
        return;
    m_color = color;
    emit colorChanged();
    update();
}

void MapScaleBar::geometryChange(const QRectF &newGeometry, const QRectF &oldGeometry)
{
    QQuickPaintedItem::geometryChange(newGeometry, oldGeometry);
    recompute();
}

void MapScaleBar::recompute()
{
    const ScaleBarLength length = m_map ? ScaleBarLength::choose(m_map->metersPerPixel(), width() - 4, m_imperial)
                                        : ScaleBarLength{};
    if (length.label == m_length.label && qFuzzyCompare(length.pixels + 1, m_length.pixels + 1))
        return;
    m_length = length;
    emit scaleChanged();
    update();
}

void MapScaleBar::paint(QPainter *painter)
{
    if (m_length.pixels <= 0)
        return;
    const double bottom = height() - 3;
    const double right = 2 + m_length.pixels;
    QPen halo(QColor(m_color.lightnessF() < 0.5 ? Qt::white : Qt::black), 4);
    halo.setCapStyle(Qt::FlatCap);
    QPen pen(m_color, 2);
    pen.setCapStyle(Qt::FlatCap);
    const QPolygonF bar({QPointF(2, bottom - 6), QPointF(2, bottom), QPointF(right, bottom), QPointF(right, bottom - 6)});
    painter->setPen(halo);
    painter->drawPolyline(bar);
    painter->setPen(pen);
    painter->drawPolyline(bar);
    QFont font = painter->font();
    font.setPixelSize(11);
    painter->setFont(font);
    painter->drawText(QRectF(4, 0, std::max(60.0, m_length.pixels), bottom - 7), Qt::AlignLeft | Qt::AlignBottom,
                      m_length.label);
}

} // namespace sortie::ui
