#pragma once

#include <QPointF>
#include <QRectF>
#include <QSizeF>

#include <vector>

namespace sortie::ui {

// Lays out the labels of marks on a map (vehicles, each drawn as an arrow) so that no two
// labels overlap and no label covers another mark: a label goes beside its mark unless a label
// placed earlier or another mark is there; then it is stacked below the one in the way (drawn
// with a leader line). Labels placed first keep their place: place the most important first.
class LabelPlacer
{
public:
    struct Placement
    {
        QRectF rect;
        bool moved = false; // stacked away from its mark
    };

    // The marks no label may cover, except the mark's own label; `markSize` 0: the marks are only
    // where labels go (nothing is drawn there to keep clear).
    explicit LabelPlacer(std::vector<QPointF> marks, qreal markSize = kMarkSize);

    // Places the label of `marks[mark]` of this size and keeps it for the labels after it.
    Placement place(size_t mark, QSizeF size);
    // A label another layer drew there: the labels placed after keep clear of it.
    void keepClear(const QRectF &label) { m_placed.push_back(label); }

    // How far from its mark a label starts, and how large a mark is kept clear.
    static constexpr QPointF kOffset{16, -10};
    static constexpr qreal kMarkSize = 24;
    // A label is moved down this many times at most (then it stays where it got to).
    static constexpr int kMaxMoves = 12;

private:
    bool blocked(size_t mark, const QRectF &rect) const;

    std::vector<QPointF> m_marks;
    qreal m_markSize;
    std::vector<QRectF> m_placed;
};

} // namespace sortie::ui
