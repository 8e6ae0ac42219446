#include "EditZoneCommand.h"

#include "Airspace.h"

namespace sortie::airspace {

EditZoneCommand::EditZoneCommand(Airspace *store, int index, Zone before, Zone after, const QString &text, QString kind, int gesture)
    : QUndoCommand(text), m_store(store), m_index(index), m_before(std::move(before)), m_after(std::move(after)),
      m_kind(std::move(kind)), m_gesture(gesture)
{
}

void EditZoneCommand::redo()
{
    m_store->replaceCustomZone(m_index, m_after);
}

void EditZoneCommand::undo()
{
    m_store->replaceCustomZone(m_index, m_before);
}

bool EditZoneCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = static_cast<const EditZoneCommand *>(other);
    if (m_gesture == 0 || o->m_gesture != m_gesture || o->m_store != m_store || o->m_kind != m_kind || o->m_index != m_index)
        return false;
    m_after = o->m_after;
    return true;
}

} // namespace sortie::airspace
