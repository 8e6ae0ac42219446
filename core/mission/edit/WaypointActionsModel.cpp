#include "WaypointActionsModel.h"
#include "LanguageChange.h"
#include "TypedNumber.h"

#include "RouteEditor.h"
#include "RouteModel.h"

#include <algorithm>

namespace sortie::mission {

namespace {
ActionFieldRow::Kind rowKind(ActionField::Type t)
{
    switch (t) {
    case ActionField::Type::Number: return ActionFieldRow::Kind::Number;
    case ActionField::Type::Integer: return ActionFieldRow::Kind::Integer;
    case ActionField::Type::Toggle: return ActionFieldRow::Kind::Toggle;
    case ActionField::Type::Choice: return ActionFieldRow::Kind::Choice;
    }
    return ActionFieldRow::Kind::Number;
}

const std::vector<WaypointAction> *actionsAt(const RouteModel &model, int row)
{
    const Waypoint *w = row >= 0 && row < model.count() ? asWaypoint(model.segment(row)) : nullptr;
    return w ? &w->actions : nullptr;
}
} // namespace

WaypointActionsModel::WaypointActionsModel(RouteModel *model, RouteEditor *editor, QObject *parent)
    : QAbstractListModel(parent), m_model(model), m_editor(editor)
{
    i18n::refreshOnLanguageChange(this); // labels, units and summaries are translated in data()
    connect(model, &QAbstractItemModel::dataChanged, this, [this](const QModelIndex &from, const QModelIndex &to) {
        for (int row : std::as_const(m_waypoints))
            if (row >= from.row() && row <= to.row())
                return reload();
    });
    // Rows moved or went: what was selected is for the selection's owner to say again.
    connect(model, &QAbstractItemModel::modelReset, this, [this] { setRows(m_rows); });
    connect(model, &QAbstractItemModel::layoutChanged, this, [this] { setRows(m_rows); });
    connect(model, &QAbstractItemModel::rowsRemoved, this, [this] { setRows(m_rows); });
    connect(model, &QAbstractItemModel::rowsInserted, this, [this] { setRows(m_rows); });
}

void WaypointActionsModel::setRows(const QList<int> &rows)
{
    QList<int> waypoints;
    for (int row : rows)
        if (actionsAt(*m_model, row))
            waypoints << row;
    // Not QList's ==: Qt 6.4 memcmp()s an empty list's null data (UBSan: nonnull-attribute).
    const auto equal = [](const QList<int> &a, const QList<int> &b) { return std::ranges::equal(a, b); };
    const bool same = equal(rows, m_rows) && equal(waypoints, m_waypoints);
    m_rows = rows;
    m_waypoints = std::move(waypoints);
    reload();
    if (same)
        return;
    setProblem({});
    emit rowsChanged();
}

void WaypointActionsModel::reload()
{
    // Same kinds in the same places: the rows change in place, so an editor keeps its fields.
    std::vector<QString> kinds;
    if (const auto *actions = shown())
        for (const WaypointAction &a : *actions)
            kinds.push_back(actionKindName(a));
    if (kinds == m_kinds && !kinds.empty()) {
        emit dataChanged(index(0), index(int(kinds.size()) - 1));
    } else {
        beginResetModel();
        m_kinds = std::move(kinds);
        endResetModel();
    }
    emit actionsChanged();
}

void WaypointActionsModel::setProblem(const QString &problem)
{
    if (problem == m_problem)
        return;
    m_problem = problem;
    emit problemChanged();
}

const std::vector<WaypointAction> *WaypointActionsModel::shown() const
{
    return m_waypoints.isEmpty() ? nullptr : actionsAt(*m_model, m_waypoints.first());
}

QString WaypointActionsModel::title() const
{
    if (m_waypoints.isEmpty())
        return {};
    if (m_waypoints.size() == 1)
        return tr("Actions at waypoint %1").arg(m_waypoints.first() + 1);
    return tr("Actions at %1 waypoints").arg(m_waypoints.size());
}

bool WaypointActionsModel::isMixed() const
{
    const auto *first = shown();
    for (int row : m_waypoints)
        if (const auto *a = actionsAt(*m_model, row); first && a && *a != *first)
            return true;
    return false;
}

QList<ActionKindChoice> WaypointActionsModel::kindChoices() const
{
    QList<ActionKindChoice> list;
    for (const ActionKindDescription &k : editableActionKinds())
        list << ActionKindChoice{k.kind, actionText(k.label)};
    return list;
}

QStringList WaypointActionsModel::kindLabels() const
{
    QStringList labels;
    for (const ActionKindChoice &k : kindChoices())
        labels << k.label;
    return labels;
}

QList<ActionFieldRow> WaypointActionsModel::fieldsOf(int row) const
{
    QList<ActionFieldRow> fields;
    const auto *actions = shown();
    if (!actions || row < 0 || row >= int(actions->size()))
        return fields;
    const WaypointAction &action = (*actions)[size_t(row)];
    const ActionKindDescription *description = actionKindDescription(actionKindName(action));
    if (!description)
        return fields;
    const QVariantMap values = actionToVariant(action);
    for (const ActionField &f : description->fields) {
        ActionFieldRow field;
        field.action = row;
        field.name = f.name;
        field.label = actionText(f.label);
        field.unit = actionText(f.unit);
        field.kind = rowKind(f.type);
        field.value = values.value(f.name);
        field.optional = f.optional;
        if (field.hasValue() && field.isNumber())
            field.text = field.value.toString();
        for (const auto &[value, label] : f.choices) {
            if (field.hasValue() && field.value.toString() == value)
                field.choiceIndex = int(field.choiceTexts.size());
            field.choiceTexts << actionText(label);
            field.choiceValues << value;
        }
        fields << field;
    }
    return fields;
}

int WaypointActionsModel::rowCount(const QModelIndex &parent) const
{
    const auto *actions = shown();
    return parent.isValid() || !actions ? 0 : int(actions->size());
}

QHash<int, QByteArray> WaypointActionsModel::roleNames() const
{
    return {{KindRole, "kind"}, {LabelRole, "label"}, {SummaryRole, "summary"}, {FieldsRole, "fields"}, {EditableRole, "editable"}};
}

QVariant WaypointActionsModel::data(const QModelIndex &index, int role) const
{
    const auto *actions = shown();
    if (!actions || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const WaypointAction &action = (*actions)[size_t(index.row())];
    const ActionKindDescription *description = actionKindDescription(actionKindName(action));
    switch (role) {
    case KindRole: return actionKindName(action);
    case LabelRole: return description ? actionText(description->label) : describeAction(action);
    case SummaryRole: return describeAction(action);
    case EditableRole: return description != nullptr;  // a server's action Sortie does not model is kept, not edited
    case FieldsRole: {
        QVariantList fields;
        for (const ActionFieldRow &f : fieldsOf(index.row()))
            fields << QVariant::fromValue(f);
        return fields;
    }
    default: return {};
    }
}

QList<int> WaypointActionsModel::rowsWithShown(int action) const
{
    QList<int> rows;
    const auto *actions = shown();
    if (!actions || action < 0 || action >= int(actions->size()))
        return rows;
    const WaypointAction shownAction = (*actions)[size_t(action)];
    for (int row : m_waypoints)
        if (const auto *a = actionsAt(*m_model, row); a && action < int(a->size()) && (*a)[size_t(action)] == shownAction)
            rows << row;
    return rows;
}

bool WaypointActionsModel::add(const QString &kind)
{
    if (!actionKindDescription(kind)) {
        setProblem(tr("There is no action \"%1\".").arg(kind));
        return false;
    }
    setProblem({});
    return m_editor->addAction(m_waypoints, {{QStringLiteral("kind"), kind}});
}

bool WaypointActionsModel::addKindAt(int index)
{
    const QList<ActionKindChoice> kinds = kindChoices();
    if (index < 0 || index >= kinds.size()) {
        setProblem(tr("Choose an action to add."));
        return false;
    }
    return add(kinds[index].kind);
}

bool WaypointActionsModel::setField(int action, const QString &name, const QVariant &value)
{
    const QList<int> rows = rowsWithShown(action);
    if (rows.isEmpty())
        return false;
    const WaypointAction &current = (*shown())[size_t(action)];
    const ActionKindDescription *description = actionKindDescription(actionKindName(current));
    const ActionField *field = nullptr;
    if (description)  // (a ?: with an empty vector would copy the fields and leave `field` dangling)
        for (const ActionField &f : description->fields)
            if (f.name == name)
                field = &f;
    if (!field) {
        setProblem(tr("This action has no field \"%1\".").arg(name));
        return false;
    }
    const bool numeric = field->type == ActionField::Type::Number || field->type == ActionField::Type::Integer;
    QVariant typed = value;
    if (numeric && value.typeId() == QMetaType::QString)  // as typed: "2,5" in German, or with a dot
        if (const std::optional<double> n = i18n::parseTypedNumber(value.toString()))
            typed = *n;
    if (const QString why = field->check(typed); !why.isEmpty()) {
        setProblem(why);
        return false;
    }
    setProblem({});
    QVariantMap changed = actionToVariant(current);
    if (numeric && field->optional && typed.toString().trimmed().isEmpty())
        changed.remove(name);  // unset
    else
        changed.insert(name, numeric ? QVariant(typed.toDouble()) : typed);
    return m_editor->setAction(rows, action, changed);
}

void WaypointActionsModel::remove(int action)
{
    const QList<int> rows = rowsWithShown(action);
    if (!rows.isEmpty())
        m_editor->removeAction(rows, action);
}

void WaypointActionsModel::clear()
{
    if (!m_waypoints.isEmpty())
        m_editor->clearActions(m_waypoints);
}

} // namespace sortie::mission
