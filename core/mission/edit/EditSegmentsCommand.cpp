#include "EditSegmentsCommand.h"

#include "RouteModel.h"

namespace sortie::mission {

EditSegmentsCommand::EditSegmentsCommand(RouteModel *model, std::vector<int> rows, std::vector<Segment> before,
                                         std::vector<Segment> after, const QString &text, QString kind, int gesture)
    : QUndoCommand(text), m_model(model), m_rows(std::move(rows)), m_before(std::move(before)), m_after(std::move(after)),
      m_kind(std::move(kind)), m_gesture(gesture)
{
}

void EditSegmentsCommand::redo()
{
    m_model->replaceSegments(m_rows, m_after);
}

void EditSegmentsCommand::undo()
{
    m_model->replaceSegments(m_rows, m_before);
}

bool EditSegmentsCommand::mergeWith(const QUndoCommand *other)
{
    const auto *o = static_cast<const EditSegmentsCommand *>(other);
    if (m_gesture == 0 || o->m_gesture != m_gesture || o->m_model != m_model || o->m_kind != m_kind || o->m_rows != m_rows)
        return false;
    m_after = o->m_after;
    return true;
}

} // namespace sortie::mission
