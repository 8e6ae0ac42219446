#include "MoveWaypointCommand.h"

#include "RouteModel.h"

namespace sortie::mission {

MoveWaypointCommand::MoveWaypointCommand(RouteModel *model, int row, const GeoPoint &to, int gesture)
    : QUndoCommand(QStringLiteral("Move waypoint %1").arg(row + 1)), m_model(model), m_row(row), m_gesture(gesture),
      m_from(std::get<Waypoint>(model->segment(row)).position), m_to(to)
{
}

void MoveWaypointCommand::redo()
{
    m_model->setWaypointPosition(m_row, m_to);
}

void MoveWaypointCommand::undo()
{
    m_model->setWaypointPosition(m_row, m_from);
}

bool MoveWaypointCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = static_cast<const MoveWaypointCommand *>(other);
    if (o->m_model != m_model || o->m_row != m_row || m_gesture == kNoMerge || o->m_gesture != m_gesture)
        return false;
    m_to = o->m_to;
    return true;
}

} // namespace sortie::mission
