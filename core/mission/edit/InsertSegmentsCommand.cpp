#include "InsertSegmentsCommand.h"

#include "RouteModel.h"

#include <numeric>

namespace sortie::mission {

InsertSegmentsCommand::InsertSegmentsCommand(RouteModel *model, int row, std::vector<Segment> segments, const QString &text)
    : QUndoCommand(text), m_model(model), m_row(row), m_segments(std::move(segments)), m_count(int(m_segments.size()))
{
}

void InsertSegmentsCommand::redo()
{
    m_model->insertSegments(m_row, std::move(m_segments));
    m_segments.clear();
}

void InsertSegmentsCommand::undo()
{
    std::vector<int> rows(static_cast<size_t>(m_count));
    std::iota(rows.begin(), rows.end(), m_row);
    m_segments = m_model->takeSegments(rows);
}

} // namespace sortie::mission
