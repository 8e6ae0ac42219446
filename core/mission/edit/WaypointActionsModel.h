#pragma once

#include "ActionFieldRow.h"
#include "ActionVariants.h"

#include <QAbstractListModel>
#include <QList>

namespace sortie::mission {

class RouteEditor;
class RouteModel;

// The actions at the selected waypoints, for an editor: one row per action of the first selected
// waypoint, each with its fields (ActionVariants.h) to edit. Adding and clearing apply to every
// selected waypoint; editing or removing an action applies to each selected waypoint that has the
// same action at that place, so a selection with different actions is never overwritten by the one
// shown. Every change goes through the RouteEditor: validated, one undo step.
class WaypointActionsModel : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(QList<int> rows READ rows WRITE setRows NOTIFY rowsChanged)
    Q_PROPERTY(bool valid READ isValid NOTIFY rowsChanged)   // a waypoint is among the rows
    Q_PROPERTY(QString title READ title NOTIFY rowsChanged)
    Q_PROPERTY(bool mixed READ isMixed NOTIFY actionsChanged) // the selected waypoints' actions differ
    Q_PROPERTY(int count READ count NOTIFY actionsChanged)
    Q_PROPERTY(QString problem READ problem NOTIFY problemChanged)
    Q_PROPERTY(QStringList kindLabels READ kindLabels CONSTANT)  // the "add" menu, in kindChoices() order

public:
    // FieldsRole: the action's fields as ActionFieldRow values (fieldsOf).
    enum Roles { KindRole = Qt::UserRole + 1, LabelRole, SummaryRole, FieldsRole, EditableRole };
    Q_ENUM(Roles)

    WaypointActionsModel(RouteModel *model, RouteEditor *editor, QObject *parent = nullptr);

    QList<int> rows() const { return m_rows; }
    void setRows(const QList<int> &rows);
    bool isValid() const { return !m_waypoints.isEmpty(); }
    QString title() const;
    bool isMixed() const;
    QString problem() const { return m_problem; }
    int count() const { return rowCount(); }
    QList<ActionKindChoice> kindChoices() const;
    QStringList kindLabels() const;
    QList<ActionFieldRow> fieldsOf(int action) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

    Q_INVOKABLE bool add(const QString &kind);
    Q_INVOKABLE bool addKindAt(int index);  // the kindChoices() entry, as the "add" menu offers it
    // `value` checked against the field's type and range; a refusal sets problem.
    Q_INVOKABLE bool setField(int action, const QString &name, const QVariant &value);
    Q_INVOKABLE void remove(int action);
    Q_INVOKABLE void clear();

signals:
    void rowsChanged();
    void actionsChanged();
    void problemChanged();

private:
    const std::vector<WaypointAction> *shown() const;  // the first selected waypoint's actions
    QList<int> rowsWithShown(int action) const;        // selected waypoints with that action there
    void reload();
    void setProblem(const QString &problem);

    RouteModel *m_model;
    RouteEditor *m_editor;
    QList<int> m_rows;
    QList<int> m_waypoints;  // the rows that are waypoints
    std::vector<QString> m_kinds;  // what the views show, to tell an edit from a new list
    QString m_problem;
};

} // namespace sortie::mission
