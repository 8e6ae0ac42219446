#include "LayerCanvas.h"

#include <QPainter>

namespace sortie::ui {

LayerCanvas::LayerCanvas(QQuickItem *parent, Painter painter)
    : QQuickPaintedItem(parent)
    , m_painter(std::move(painter))
{
    setAntialiasing(true);
    setAcceptedMouseButtons(Qt::NoButton);
}

void LayerCanvas::paint(QPainter *painter)
{
    ++m_paints;
    if (m_painter)
        m_painter(*painter);
}

} // namespace sortie::ui
