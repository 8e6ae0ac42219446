#pragma once

#include "RouteValidator.h"

#include <QAbstractListModel>

namespace sortie::mission {

// The validation list for a view: one row per issue.
class ValidationIssueModel : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    enum Roles {
        SeverityRole = Qt::UserRole + 1,  // "error" / "warning"
        RuleRole,                         // stable rule id, e.g. "altitude-above-max"
        MessageRole,
        SegmentRole,                      // 0-based row of the offending segment, -1 for the route
    };

    explicit ValidationIssueModel(QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = QModelIndex()) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;
    int count() const { return int(m_report.issues.size()); }

    void setReport(const ValidationReport &report);
    const ValidationReport &report() const { return m_report; }

signals:
    void countChanged();

private:
    ValidationReport m_report;
};

} // namespace sortie::mission
