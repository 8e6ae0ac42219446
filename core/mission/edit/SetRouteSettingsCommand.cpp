#include "SetRouteSettingsCommand.h"

#include "RouteModel.h"

namespace sortie::mission {

SetRouteSettingsCommand::SetRouteSettingsCommand(RouteModel *model, RouteSettings settings, const QString &text)
    : QUndoCommand(text), m_model(model), m_before(model->settings()), m_after(std::move(settings))
{
}

void SetRouteSettingsCommand::redo()
{
    m_model->setSettings(m_after);
}

void SetRouteSettingsCommand::undo()
{
    m_model->setSettings(m_before);
}

} // namespace sortie::mission
