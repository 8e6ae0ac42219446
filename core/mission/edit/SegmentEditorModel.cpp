#include "SegmentEditorModel.h"
#include "LanguageChange.h"
#include "TypedNumber.h"

#include "AreaScanPlanner.h"
#include "RouteEditor.h"
#include "RouteModel.h"
#include "SegmentParameters.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace sortie::mission {

namespace {
// The definitions that describe a segment's parameters, most specific first.
std::vector<const AlgorithmDefinition *> definitionsOf(const Segment &s, const AlgorithmCatalog &catalog)
{
    std::vector<const AlgorithmDefinition *> out;
    auto add = [&](const AlgorithmDefinition *d) {
        if (d)
            out.push_back(d);
    };
    if (const Waypoint *w = asWaypoint(s)) {
        add(catalog.byKind(w->role == WaypointRole::Takeoff ? AlgorithmKind::TakeOff
                           : w->role == WaypointRole::Land ? AlgorithmKind::Landing : AlgorithmKind::Waypoint));
        add(catalog.byKind(AlgorithmKind::Waypoint));
    } else if (isAreaScan(s)) {
        // Sortie's area scan flies a camera too: the photogrammetry tool describes those names.
        add(catalog.byKind(AlgorithmKind::AreaScan));
        add(catalog.byKind(AlgorithmKind::Photogrammetry));
    } else {
        add(catalog.byClassName(std::get<AlgorithmSegment>(s).algorithm));
    }
    return out;
}

// Names Sortie itself gives (docs/missions.md): described here, since no server does.
std::optional<ParameterDefinition> sortieDefinition(const QString &name)
{
    struct Own { const char *name; const char *label; ParameterType type; Quantity quantity; double minimum; };
    static const Own kOwn[] = {
        {"acceptanceRadius", QT_TRANSLATE_NOOP("SegmentEditorModel", "Acceptance radius"), ParameterType::Double, Quantity::Distance, 0},
        {"cameraSensorWidth", QT_TRANSLATE_NOOP("SegmentEditorModel", "Sensor width (mm)"), ParameterType::Double, Quantity::None, 0.01},
        {"cameraSensorHeight", QT_TRANSLATE_NOOP("SegmentEditorModel", "Sensor height (mm)"), ParameterType::Double, Quantity::None, 0.01},
        {"cameraFocalLength", QT_TRANSLATE_NOOP("SegmentEditorModel", "Focal length (mm)"), ParameterType::Double, Quantity::None, 0.01},
        {"cameraImageWidth", QT_TRANSLATE_NOOP("SegmentEditorModel", "Image width (px)"), ParameterType::Integer, Quantity::Count, 1},
        {"cameraImageHeight", QT_TRANSLATE_NOOP("SegmentEditorModel", "Image height (px)"), ParameterType::Integer, Quantity::Count, 1},
        {"height", QT_TRANSLATE_NOOP("SegmentEditorModel", "Height"), ParameterType::Double, Quantity::Altitude, 0.1},
        {"sideDistance", QT_TRANSLATE_NOOP("SegmentEditorModel", "Side distance (0: from the camera)"), ParameterType::Double, Quantity::Distance, 0},
    };
    for (const Own &o : kOwn) {
        if (name == QLatin1String(o.name)) {
            ParameterDefinition d;
            d.name = name;
            d.displayName = QCoreApplication::translate("SegmentEditorModel", o.label);
            d.type = o.type;
            d.quantity = o.quantity;
            d.minimum = o.minimum;
            d.advanced = name.startsWith(QLatin1String("camera"));
            return d;
        }
    }
    return std::nullopt;
}

QString typeName(ParameterType t)
{
    switch (t) {
    case ParameterType::String: return QStringLiteral("string");
    case ParameterType::Integer: return QStringLiteral("integer");
    case ParameterType::Double: return QStringLiteral("double");
    case ParameterType::Boolean: return QStringLiteral("boolean");
    case ParameterType::Selection: return QStringLiteral("selection");
    }
    return QStringLiteral("string");
}

QString widgetOf(const ParameterDefinition &d)
{
    if (d.name == QLatin1String("camera"))
        return QStringLiteral("camera");
    if (d.quantity == Quantity::Angle)
        return QStringLiteral("angle");
    switch (d.type) {
    case ParameterType::Boolean: return QStringLiteral("toggle");
    case ParameterType::Selection: return d.choices.empty() ? QStringLiteral("text") : QStringLiteral("choice");
    case ParameterType::Integer:
    case ParameterType::Double: return QStringLiteral("number");
    case ParameterType::String: break;
    }
    return QStringLiteral("text");
}

QString textOf(const QVariant &v)
{
    if (v.metaType().id() == QMetaType::Double)
        return parameterNumberText(v.toDouble());
    if (v.metaType().id() == QMetaType::Bool)
        return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    return v.toString();
}
} // namespace

SegmentEditorModel::SegmentEditorModel(RouteModel *model, RouteEditor *editor, QObject *parent)
    : QAbstractListModel(parent), m_model(model), m_editor(editor)
{
    i18n::onLanguageChange(this, [this] { rebuild(); }); // the fields' names are made in the language of the day
    connect(model, &QAbstractItemModel::dataChanged, this, [this](const QModelIndex &from, const QModelIndex &to) {
        if (m_row >= from.row() && m_row <= to.row())
            refreshValues();
    });
    connect(model, &QAbstractItemModel::modelReset, this, &SegmentEditorModel::rebuild);
    connect(model, &QAbstractItemModel::layoutChanged, this, &SegmentEditorModel::rebuild);
    connect(model, &QAbstractItemModel::rowsRemoved, this, &SegmentEditorModel::rebuild);
    connect(model, &QAbstractItemModel::rowsInserted, this, &SegmentEditorModel::rebuild);
    connect(editor, &RouteEditor::catalogChanged, this, &SegmentEditorModel::rebuild);
    connect(editor, &RouteEditor::refused, this, [this](const QString &reason) {
        m_problem = reason;
        emit valuesChanged();
    });
}

const Segment *SegmentEditorModel::segment() const
{
    return m_model && m_row >= 0 && m_row < m_model->count() ? &m_model->segment(m_row) : nullptr;
}

void SegmentEditorModel::setRow(int row)
{
    if (row == m_row)
        return;
    m_row = row;
    m_problem.clear();
    rebuild();
    emit rowChanged();
}

void SegmentEditorModel::rebuild()
{
    beginResetModel();
    m_fields.clear();
    if (const Segment *s = segment(); s && !isWaypoint(*s)) {
        const AlgorithmCatalog &catalog = m_editor->catalog();
        const auto definitions = definitionsOf(*s, catalog);
        for (const QString &name : parameterNames(*s, catalog)) {
            Field f{name, {}, false};
            // Sortie's own area scan reads some names its own way (sideDistance 0: from the camera),
            // so its own descriptions come first there; elsewhere the server's do.
            std::optional<ParameterDefinition> found = isAreaScan(*s) ? sortieDefinition(name) : std::nullopt;
            for (const AlgorithmDefinition *d : definitions)
                if (const ParameterDefinition *p = found ? nullptr : d->parameter(name))
                    found = *p;
            if (!found)
                found = sortieDefinition(name);
            if (found) {
                f.definition = *found;
                f.known = true;
            } else {
                f.definition.name = name;
                f.definition.displayName = name;
                f.definition.description = tr("A parameter Sortie has no description of: kept and sent as typed.");
            }
            if (f.definition.displayName.isEmpty())
                f.definition.displayName = name;
            if (name == QLatin1String("camera") && f.definition.choices.empty()) {
                // The vehicle profile's cameras first (by id, as the server resolves them; an algorithm
                // segment is planned against them), then Sortie's survey cameras by name.
                if (asAlgorithmSegment(*s))
                    for (const ProfileCamera &c : m_model->settings().profile.cameras)
                        f.definition.choices.push_back({c.id > 0 ? QString::number(c.id) : c.camera.name,
                                                        tr("%1 (vehicle profile)").arg(c.camera.name)});
                for (const Camera &c : builtInCameras())
                    f.definition.choices.push_back({c.name, c.name});
                f.choicesSuggested = true;
            }
            m_fields.push_back(std::move(f));
        }
    }
    endResetModel();
    emit rowChanged();
    emit valuesChanged();
}

void SegmentEditorModel::refreshValues()
{
    const Segment *s = segment();
    if (!s)
        return rebuild();
    if (int(parameterNames(*s, m_editor->catalog()).size()) != int(m_fields.size()))
        return rebuild();  // a raw parameter came or went
    m_problem.clear();
    if (!m_fields.empty())
        emit dataChanged(index(0), index(int(m_fields.size()) - 1), {ValueRole, ValueTextRole, ProblemRole});
    emit valuesChanged();
}

int SegmentEditorModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_fields.size());
}

QHash<int, QByteArray> SegmentEditorModel::roleNames() const
{
    return {{NameRole, "name"}, {LabelRole, "label"}, {DescriptionRole, "description"}, {TypeRole, "type"}, {WidgetRole, "widget"},
            {UnitRole, "unit"}, {ValueRole, "value"}, {DefaultRole, "defaultValue"}, {MinimumRole, "minimum"},
            {MaximumRole, "maximum"}, {ChoicesRole, "choices"}, {AdvancedRole, "advanced"}, {KnownRole, "known"},
            {ProblemRole, "problem"}, {ValueTextRole, "valueText"}, {DefaultTextRole, "defaultText"}};
}

QVariant SegmentEditorModel::data(const QModelIndex &index, int role) const
{
    const Segment *s = segment();
    if (!s || !checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    const Field &f = m_fields[size_t(index.row())];
    const ParameterDefinition &d = f.definition;
    switch (role) {
    case NameRole: return f.name;
    case LabelRole: return d.displayName;
    case DescriptionRole: return d.description;
    case TypeRole: return typeName(d.type);
    case WidgetRole: return f.known ? widgetOf(d) : QStringLiteral("text");
    case UnitRole: return d.unit();
    case ValueRole: return parameterValue(*s, f.name, m_editor->catalog());
    case DefaultRole: return d.defaultValue;
    case MinimumRole: return d.minimum ? QVariant(*d.minimum) : QVariant();
    case MaximumRole: return d.maximum ? QVariant(*d.maximum) : QVariant();
    case ChoicesRole: {
        QVariantList list;
        for (const ParameterChoice &c : d.choices)
            list << QVariantMap{{QStringLiteral("value"), c.value}, {QStringLiteral("text"), c.displayName}};
        // A value outside Sortie's suggestions (a custom camera) is listed, so the picker can show it.
        const QString current = textOf(parameterValue(*s, f.name, m_editor->catalog()));
        const bool listed = std::any_of(d.choices.begin(), d.choices.end(), [&](const ParameterChoice &c) { return c.value == current; });
        if (f.choicesSuggested && !current.isEmpty() && !listed)
            list.prepend(QVariantMap{{QStringLiteral("value"), current}, {QStringLiteral("text"), current}});
        return list;
    }
    case AdvancedRole: return d.advanced;
    case KnownRole: return f.known;
    case ValueTextRole: {
        const QVariant v = parameterValue(*s, f.name, m_editor->catalog());
        if (!v.isValid())
            return QString();
        if (d.type == ParameterType::Double && f.known) // a computed GSD is 1.6473684...: show what matters
            return i18n::formatTypedNumber(std::round(v.toDouble() * 100) / 100);
        return textOf(v);
    }
    case DefaultTextRole: {
        const bool number = f.known && (d.type == ParameterType::Double || d.type == ParameterType::Integer);
        if (const auto n = number ? parseParameterNumber(d.defaultValue) : std::nullopt)
            return i18n::formatTypedNumber(*n);
        return d.defaultValue;
    }
    case ProblemRole: {
        const QVariant v = parameterValue(*s, f.name, m_editor->catalog());
        if (!f.known || !v.isValid())
            return QString();
        if (f.choicesSuggested) {  // suggestions do not restrict
            ParameterDefinition open = d;
            open.choices.clear();
            return open.check(textOf(v));
        }
        return d.check(textOf(v));
    }
    default: return {};
    }
}

QString SegmentEditorModel::title() const
{
    const Segment *s = segment();
    if (!s)
        return {};
    if (const AlgorithmSegment *a = asAlgorithmSegment(*s))  // the name the server gives it
        if (const AlgorithmDefinition *d = m_editor->catalog().byClassName(a->algorithm); d && !d->displayName.isEmpty())
            return QStringLiteral("%1 %2").arg(d->displayName).arg(m_row + 1);
    return segmentLabel(m_row, *s);
}

QString SegmentEditorModel::kind() const
{
    const Segment *s = segment();
    return s ? segmentKindName(*s) : QString();
}

bool SegmentEditorModel::isValid() const
{
    const Segment *s = segment();
    return s && !isWaypoint(*s);
}

double SegmentEditorModel::radius() const
{
    const Segment *s = segment();
    const AlgorithmSegment *a = s ? asAlgorithmSegment(*s) : nullptr;
    return a && a->figure == FigureType::Circle && !a->figureParameters.empty() ? a->figureParameters[0] : std::nan("");
}

std::optional<SegmentEditorModel::SurveyFigures> SegmentEditorModel::figures() const
{
    const Segment *s = segment();
    const std::optional<AreaScan> scan = s ? scanOf(*s, m_model->settings().profile.cameras) : std::nullopt;
    if (!scan)
        return std::nullopt;
    SurveyFigures f;
    f.height = scanAltitude(scan->parameters);
    f.gsdCm = scanGroundSampleDistanceCm(scan->parameters);
    f.footprintAcross = footprintAcrossMeters(scan->parameters);
    f.footprintAlong = footprintAlongMeters(scan->parameters);
    if (std::optional<AreaScanOutcome> outcome = m_model->scanPlan(m_row)) {
        f.plan = std::move(outcome->plan);
        f.message = outcome->message;
    }
    return f;
}

QString SegmentEditorModel::figuresText() const
{
    const std::optional<SurveyFigures> f = figures();
    if (!f)
        return {};
    if (!f->plan)
        return f->message;
    const auto n = [](double v, int decimals) { return QString::number(v, 'f', decimals); };
    return tr("%1 m high · %2 cm/px · footprint %3 × %4 m · passes %5 m apart · photo every %6 m · %7 photos")
        .arg(n(f->height, 1), n(f->gsdCm, 2), n(f->footprintAcross, 1), n(f->footprintAlong, 1), n(f->plan->transectSpacing, 1),
             n(f->plan->triggerDistance, 1))
        .arg(f->plan->photoCount);
}

QStringList SegmentEditorModel::cameras() const
{
    QStringList names;
    for (const Camera &c : builtInCameras())
        names << c.name;
    return names;
}

bool SegmentEditorModel::set(int index, const QVariant &value, EditStep step)
{
    if (index < 0 || index >= int(m_fields.size()) || !m_editor)
        return false;
    const Field &f = m_fields[size_t(index)];
    QVariant typed = value;
    // A text field's number arrives as text; the definition says what it is.
    if (value.metaType().id() == QMetaType::QString && f.known
        && (f.definition.type == ParameterType::Double || f.definition.type == ParameterType::Integer) && !value.toString().isEmpty()) {
        const auto n = i18n::parseTypedNumber(value.toString());  // as the operator types it: "2,5" in German
        if (!n) {
            m_problem = tr("%1 needs a number, not \"%2\".").arg(f.definition.displayName, value.toString());
            emit valuesChanged();
            return false;
        }
        typed = *n;
    }
    return m_editor->setParameter({m_row}, f.name, typed, step);
}

bool SegmentEditorModel::setRadius(double meters, EditStep step)
{
    return m_editor && m_editor->setRadius(m_row, meters, step);
}

int SegmentEditorModel::indexOf(const QString &name) const
{
    for (size_t i = 0; i < m_fields.size(); ++i)
        if (m_fields[i].name == name)
            return int(i);
    return -1;
}

} // namespace sortie::mission
