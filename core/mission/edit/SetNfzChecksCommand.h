#pragma once

#include <QUndoCommand>

namespace sortie::mission {

class RouteModel;

// Turns the server's no-fly-zone checks of the route on or off (RouteSettings::checkAerodromeNfz,
// checkCustomNfz); the rest of the route's settings are left as they are at the time.
class SetNfzChecksCommand : public QUndoCommand
{
public:
    SetNfzChecksCommand(RouteModel *model, bool checkAerodrome, bool checkCustom);
    void redo() override;
    void undo() override;

private:
    void apply(bool aerodrome, bool custom);

    RouteModel *m_model;
    bool m_aerodromeBefore, m_customBefore;
    bool m_aerodromeAfter, m_customAfter;
};

} // namespace sortie::mission
