#pragma once

#include "Zone.h"

#include <QUndoCommand>

namespace sortie::airspace {

class Airspace;

// One undo step: a drawn zone added at `index` of the store's drawn zones (undo removes it).
class AddZoneCommand : public QUndoCommand
{
public:
    AddZoneCommand(Airspace *store, int index, Zone zone, const QString &text);
    void redo() override;
    void undo() override;

private:
    Airspace *m_store;
    int m_index;
    Zone m_zone;
};

} // namespace sortie::airspace
