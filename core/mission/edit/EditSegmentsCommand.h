#pragma once

#include "Segment.h"

#include <QUndoCommand>

#include <functional>
#include <vector>

namespace sortie::mission {

class RouteModel;

// One undo step for an edit of a selection: altitude, altitude type, speed, actions, scan
// parameters... The edit function is applied once, at construction, to copies of the rows; redo
// and undo swap the stored values in.
class EditSegmentsCommand : public QUndoCommand
{
public:
    EditSegmentsCommand(RouteModel *model, std::vector<int> rows, const std::function<void(Segment &)> &edit,
                        const QString &text);
    void redo() override;
    void undo() override;
    // True when the edit changes nothing (the caller may skip pushing it).
    bool isNoOp() const { return m_before == m_after; }

private:
    RouteModel *m_model;
    std::vector<int> m_rows;  // sorted, unique
    std::vector<Segment> m_before;
    std::vector<Segment> m_after;
};

} // namespace sortie::mission
