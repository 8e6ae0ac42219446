#pragma once

#include "GeoPoint.h"

#include <QUndoCommand>

namespace sortie::mission {

class RouteModel;

// Moves one waypoint. Consecutive moves of the same waypoint within one gesture (the steps of a
// drag) merge into one undo step that returns it to where the gesture found it.
class MoveWaypointCommand : public QUndoCommand
{
public:
    static constexpr int kId = 0x5301;
    static constexpr int kNoMerge = -1;  // a gesture of one step (a typed coordinate)

    MoveWaypointCommand(RouteModel *model, int row, const GeoPoint &to, int gesture = kNoMerge);
    void redo() override;
    void undo() override;
    int id() const override { return kId; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    RouteModel *m_model;
    int m_row;
    int m_gesture;
    GeoPoint m_from;
    GeoPoint m_to;
};

} // namespace sortie::mission
