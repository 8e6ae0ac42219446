#pragma once

#include "Segment.h"

#include <QUndoCommand>

#include <vector>

namespace sortie::mission {

class RouteModel;

// Deletes a selection of rows (any order, duplicates ignored). Undo puts each back at its row.
class RemoveSegmentsCommand : public QUndoCommand
{
public:
    RemoveSegmentsCommand(RouteModel *model, std::vector<int> rows);
    void redo() override;
    void undo() override;

private:
    RouteModel *m_model;
    std::vector<int> m_rows;          // sorted, unique
    std::vector<Segment> m_removed;   // held while done
};

} // namespace sortie::mission
