#include "ReorderSegmentsCommand.h"

#include "RouteModel.h"

#include <algorithm>
#include <numeric>
#include <QCoreApplication>

namespace sortie::mission {

ReorderSegmentsCommand *ReorderSegmentsCommand::moveRows(RouteModel *model, std::vector<int> rows, int destination)
{
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    const int n = model->count();
    std::vector<bool> selected(size_t(n), false);
    for (int r : rows)
        selected[size_t(r)] = true;
    std::vector<int> order;
    order.reserve(size_t(n));
    for (int i = 0; i <= n; ++i) {
        if (i == destination)
            order.insert(order.end(), rows.begin(), rows.end());
        if (i < n && !selected[size_t(i)])
            order.push_back(i);
    }
    return new ReorderSegmentsCommand(model, std::move(order),
                                      rows.size() == 1 ? QCoreApplication::translate("ReorderSegmentsCommand", "Move row %1").arg(rows.front() + 1)
                                                       : QCoreApplication::translate("ReorderSegmentsCommand", "Move %1 rows").arg(rows.size()));
}

ReorderSegmentsCommand *ReorderSegmentsCommand::reverse(RouteModel *model, int first, int last)
{
    std::vector<int> order(size_t(model->count()));
    std::iota(order.begin(), order.end(), 0);
    std::reverse(order.begin() + first, order.begin() + last + 1);
    return new ReorderSegmentsCommand(model, std::move(order), QCoreApplication::translate("ReorderSegmentsCommand", "Reverse rows %1-%2").arg(first + 1).arg(last + 1));
}

ReorderSegmentsCommand::ReorderSegmentsCommand(RouteModel *model, std::vector<int> order, const QString &text)
    : QUndoCommand(text), m_model(model), m_order(std::move(order)), m_inverse(m_order.size())
{
    for (size_t i = 0; i < m_order.size(); ++i)
        m_inverse[size_t(m_order[i])] = int(i);
}

void ReorderSegmentsCommand::redo()
{
    m_model->permute(m_order);
}

void ReorderSegmentsCommand::undo()
{
    m_model->permute(m_inverse);
}

} // namespace sortie::mission
