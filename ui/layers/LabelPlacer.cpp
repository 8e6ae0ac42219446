#include "LabelPlacer.h"

namespace sortie::ui {

LabelPlacer::LabelPlacer(std::vector<QPointF> marks, qreal markSize)
    : m_marks(std::move(marks)), m_markSize(markSize)
{
}

LabelPlacer::Placement LabelPlacer::place(size_t mark, QSizeF size)
{
    Placement placement;
    placement.rect = QRectF(m_marks.at(mark) + kOffset - QPointF(0, size.height() / 2), size);
    for (int tries = 0; tries < kMaxMoves && blocked(mark, placement.rect); ++tries) {
        placement.rect.translate(0, size.height() + 1);
        placement.moved = true;
    }
    m_placed.push_back(placement.rect);
    return placement;
}

bool LabelPlacer::blocked(size_t mark, const QRectF &rect) const
{
    for (const QRectF &other : m_placed)
        if (rect.intersects(other))
            return true;
    if (m_markSize <= 0)
        return false;
    const QPointF half(m_markSize / 2, m_markSize / 2);
    for (size_t other = 0; other < m_marks.size(); ++other)
        if (other != mark && rect.intersects(QRectF(m_marks[other] - half, QSizeF(m_markSize, m_markSize))))
            return true;
    return false;
}

} // namespace sortie::ui
