#include "RemoveSegmentsCommand.h"

#include "RouteModel.h"

#include <algorithm>
#include <QCoreApplication>

namespace sortie::mission {

RemoveSegmentsCommand::RemoveSegmentsCommand(RouteModel *model, std::vector<int> rows)
    : m_model(model), m_rows(std::move(rows))
{
    std::sort(m_rows.begin(), m_rows.end());
    m_rows.erase(std::unique(m_rows.begin(), m_rows.end()), m_rows.end());
    setText(m_rows.size() == 1 ? QCoreApplication::translate("RemoveSegmentsCommand", "Delete %1").arg(RouteModel::segmentLabelFor(m_rows.front(), model->segment(m_rows.front())))
                               : QCoreApplication::translate("RemoveSegmentsCommand", "Delete %1 rows").arg(m_rows.size()));
}

void RemoveSegmentsCommand::redo()
{
    m_removed = m_model->takeSegments(m_rows);
}

void RemoveSegmentsCommand::undo()
{
    m_model->restoreSegments(m_rows, std::move(m_removed));
    m_removed.clear();
}

} // namespace sortie::mission
