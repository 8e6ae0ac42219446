#include "AddZoneCommand.h"

#include "Airspace.h"

namespace sortie::airspace {

AddZoneCommand::AddZoneCommand(Airspace *store, int index, Zone zone, const QString &text)
    : QUndoCommand(text), m_store(store), m_index(index), m_zone(std::move(zone))
{
}

void AddZoneCommand::redo()
{
    m_store->insertCustomZone(m_index, m_zone);
}

void AddZoneCommand::undo()
{
    m_store->removeCustomZone(m_index);
}

} // namespace sortie::airspace
