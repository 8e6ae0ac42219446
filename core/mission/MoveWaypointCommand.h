#pragma once

#include "GeoPoint.h"

#include <QUndoCommand>

namespace sortie::mission {

class RouteModel;

// Moves one waypoint. Consecutive moves of the same waypoint (the steps of a drag) merge into one
// undo step that returns it to where the first one found it.
class MoveWaypointCommand : public QUndoCommand
{
public:
    static constexpr int kId = 0x5301;

    MoveWaypointCommand(RouteModel *model, int row, const GeoPoint &to);
    void redo() override;
    void undo() override;
    int id() const override { return kId; }
    bool mergeWith(const QUndoCommand *other) override;

private:
    RouteModel *m_model;
    int m_row;
    GeoPoint m_from;
    GeoPoint m_to;
};

} // namespace sortie::mission
