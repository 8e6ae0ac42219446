#pragma once

#include "Zone.h"

#include <QUndoCommand>

namespace sortie::airspace {

class Airspace;

// One undo step: a drawn zone removed (undo puts it back where it was).
class RemoveZoneCommand : public QUndoCommand
{
public:
    RemoveZoneCommand(Airspace *store, int index, Zone zone, const QString &text);
    void redo() override;
    void undo() override;

private:
    Airspace *m_store;
    int m_index;
    Zone m_zone;
};

} // namespace sortie::airspace
