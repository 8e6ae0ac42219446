#pragma once

#include <QUndoCommand>

#include <vector>

namespace sortie::mission {

class RouteModel;

// Rearranges rows by a permutation: moving a selection before a destination row, or reversing a
// range. Undo applies the inverse permutation.
class ReorderSegmentsCommand : public QUndoCommand
{
public:
    // The rows (any order) end up as one block, in their order, before the row that was at
    // destination (0..count; count = the end).
    static ReorderSegmentsCommand *moveRows(RouteModel *model, std::vector<int> rows, int destination);
    // Reverses rows first..last inclusive.
    static ReorderSegmentsCommand *reverse(RouteModel *model, int first, int last);

    void redo() override;
    void undo() override;

private:
    ReorderSegmentsCommand(RouteModel *model, std::vector<int> order, const QString &text);

    RouteModel *m_model;
    std::vector<int> m_order;    // new row i holds old row m_order[i]
    std::vector<int> m_inverse;
};

} // namespace sortie::mission
