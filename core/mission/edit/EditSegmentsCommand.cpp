#include "EditSegmentsCommand.h"

#include "RouteModel.h"

#include <algorithm>

namespace sortie::mission {

EditSegmentsCommand::EditSegmentsCommand(RouteModel *model, std::vector<int> rows, const std::function<void(Segment &)> &edit,
                                         const QString &text)
    : QUndoCommand(text), m_model(model), m_rows(std::move(rows))
{
    std::sort(m_rows.begin(), m_rows.end());
    m_rows.erase(std::unique(m_rows.begin(), m_rows.end()), m_rows.end());
    m_before.reserve(m_rows.size());
    m_after.reserve(m_rows.size());
    for (int r : m_rows) {
        m_before.push_back(model->segment(r));
        m_after.push_back(m_before.back());
        edit(m_after.back());
    }
}

void EditSegmentsCommand::redo()
{
    m_model->replaceSegments(m_rows, m_after);
}

void EditSegmentsCommand::undo()
{
    m_model->replaceSegments(m_rows, m_before);
}

} // namespace sortie::mission
