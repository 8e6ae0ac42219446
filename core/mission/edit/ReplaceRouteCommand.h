#pragma once

#include "Route.h"

#include <QUndoCommand>

namespace sortie::mission {

class RouteModel;

// Replaces the whole route (an import, a route loaded from the server). Undo brings the previous
// one back intact.
class ReplaceRouteCommand : public QUndoCommand
{
public:
    ReplaceRouteCommand(RouteModel *model, Route route, const QString &text);
    void redo() override;
    void undo() override;

private:
    RouteModel *m_model;
    Route m_other;  // the route not currently in the model
};

} // namespace sortie::mission
