#include "RemoveZoneCommand.h"

#include "Airspace.h"

namespace sortie::airspace {

RemoveZoneCommand::RemoveZoneCommand(Airspace *store, int index, Zone zone, const QString &text)
    : QUndoCommand(text), m_store(store), m_index(index), m_zone(std::move(zone))
{
}

void RemoveZoneCommand::redo()
{
    m_store->removeCustomZone(m_index);
}

void RemoveZoneCommand::undo()
{
    m_store->insertCustomZone(m_index, m_zone);
}

} // namespace sortie::airspace
