#pragma once

#include <QQuickPaintedItem>

#include <functional>

namespace sortie::ui {

// One picture of a map layer: a child item that paints through a callback. The layer moves it
// (its position) instead of drawing again when the map pans by whole pixels, and sizes it to
// what it holds, because the software scene graph recomposites a changed item's whole area.
class LayerCanvas : public QQuickPaintedItem
{
    Q_OBJECT

public:
    using Painter = std::function<void(QPainter &)>;
    LayerCanvas(QQuickItem *parent, Painter painter);

    void paint(QPainter *painter) override;
    int paintCount() const { return m_paints; } // test hook: pictures drawn

private:
    Painter m_painter;
    int m_paints = 0;
};

} // namespace sortie::ui
