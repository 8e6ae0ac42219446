#include "ValidationIssueModel.h"

namespace sortie::mission {

ValidationIssueModel::ValidationIssueModel(QObject *parent) : QAbstractListModel(parent) {}

int ValidationIssueModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QHash<int, QByteArray> ValidationIssueModel::roleNames() const
{
    return {{SeverityRole, "severity"}, {RuleRole, "rule"}, {MessageRole, "message"}, {SegmentRole, "segment"},
            {Qt::DisplayRole, "display"}};
}

QVariant ValidationIssueModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const ValidationIssue &i = m_report.issues[size_t(index.row())];
    switch (role) {
    case SeverityRole: return i.severity == Severity::Error ? QStringLiteral("error") : QStringLiteral("warning");
    case RuleRole: return i.rule;
    case Qt::DisplayRole:
    case MessageRole: return i.message;
    case SegmentRole: return i.segment;
    default: return {};
    }
}

void ValidationIssueModel::setReport(const ValidationReport &report)
{
    if (report == m_report)
        return;
    const int before = count();
    beginResetModel();
    m_report = report;
    endResetModel();
    if (before != count())
        emit countChanged();
}

} // namespace sortie::mission
