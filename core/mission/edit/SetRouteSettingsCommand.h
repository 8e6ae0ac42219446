#pragma once

#include "Route.h"

#include <QUndoCommand>

namespace sortie::mission {

class RouteModel;

// Changes the route's own properties (name, limits, speeds, profile, failsafes, home).
class SetRouteSettingsCommand : public QUndoCommand
{
public:
    SetRouteSettingsCommand(RouteModel *model, RouteSettings settings, const QString &text);
    void redo() override;
    void undo() override;

private:
    RouteModel *m_model;
    RouteSettings m_before;
    RouteSettings m_after;
};

} // namespace sortie::mission
