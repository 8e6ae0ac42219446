#include "ReplaceRouteCommand.h"

#include "RouteModel.h"

namespace sortie::mission {

ReplaceRouteCommand::ReplaceRouteCommand(RouteModel *model, Route route, const QString &text)
    : QUndoCommand(text), m_model(model), m_other(std::move(route))
{
}

void ReplaceRouteCommand::redo()
{
    Route current = m_model->route();
    m_model->resetRoute(std::move(m_other));
    m_other = std::move(current);
}

void ReplaceRouteCommand::undo()
{
    redo();  // a swap is its own inverse
}

} // namespace sortie::mission
