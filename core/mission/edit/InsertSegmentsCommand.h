#pragma once

#include "Segment.h"

#include <QUndoCommand>

#include <vector>

namespace sortie::mission {

class RouteModel;

// Adds segments at a row (the end of the route to append). Undo removes them again.
class InsertSegmentsCommand : public QUndoCommand
{
public:
    InsertSegmentsCommand(RouteModel *model, int row, std::vector<Segment> segments, const QString &text);
    void redo() override;
    void undo() override;

private:
    RouteModel *m_model;
    int m_row;
    std::vector<Segment> m_segments;  // held while undone
    int m_count;
};

} // namespace sortie::mission
