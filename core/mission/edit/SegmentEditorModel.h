#pragma once

#include "AlgorithmCatalog.h"
#include "MissionEnums.h"
#include "AreaScanPlanner.h"
#include "Segment.h"

#include <QAbstractListModel>
#include <QPointer>
#include <QVariantMap>

#include <optional>

namespace sortie::mission {

class RouteEditor;
class RouteModel;

// The segment editor as a model, built from the algorithm's description the way QGroundControl
// builds its settings from Fact metadata: one row per parameter of the segment at `row`, with
// what a field needs to draw itself (type, unit, range, choices, default, description) and the
// value. The definitions come from the editor's catalog: the server's TraverseAlgorithm list when
// connected, the built-in one offline, so a new algorithm on a newer server gets a working editor
// with no code change. A value no definition names is a raw text row. Sortie's own knowledge only
// picks better widgets (`widget`: a camera picker, an angle dial). QML draws the rows and calls
// set(); every rule (ranges, parsing, what a change means) is here or below.
class SegmentEditorModel : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int row READ row WRITE setRow NOTIFY rowChanged)
    Q_PROPERTY(QString title READ title NOTIFY rowChanged)
    Q_PROPERTY(QString kind READ kind NOTIFY rowChanged)
    Q_PROPERTY(bool valid READ isValid NOTIFY rowChanged)
    // A circle's radius in metres, NaN (QML: NaN) for other figures.
    Q_PROPERTY(double radius READ radius NOTIFY valuesChanged)
    // Live figures of a survey as the operator types, in one line ("58.4 m high · 1.60 cm/px · …")
    // or why it cannot be planned; empty for a segment that is no survey.
    Q_PROPERTY(QString figuresText READ figuresText NOTIFY valuesChanged)
    Q_PROPERTY(QStringList cameras READ cameras CONSTANT)
    Q_PROPERTY(QString problem READ problem NOTIFY valuesChanged)

public:
    enum Roles {
        NameRole = Qt::UserRole + 1,  // the wire name
        LabelRole,                    // for the operator
        DescriptionRole,
        TypeRole,                     // "string", "integer", "double", "boolean", "selection"
        WidgetRole,                   // "number", "toggle", "choice", "text", "camera", "angle"
        UnitRole,                     // "m", "m/s", "%", "°", "cm/px", ...
        ValueRole,                    // typed; undefined when not set
        DefaultRole,                  // the definition's default, as text ("" = none)
        MinimumRole, MaximumRole,     // undefined when unbounded
        ChoicesRole,                  // [{value, text}] for selections
        AdvancedRole,
        KnownRole,                    // false: a raw parameter no definition names
        ProblemRole,                  // why the value is not acceptable, "" when it is
        ValueTextRole,                // the value as the field shows it (numbers to 0.01 in the UI language's format), "" when not set
        DefaultTextRole,              // the default as the field shows it (a number in the UI language's format)
    };
    Q_ENUM(Roles)

    SegmentEditorModel(RouteModel *model, RouteEditor *editor, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

    int row() const { return m_row; }
    void setRow(int row);
    QString title() const;
    QString kind() const;
    bool isValid() const;
    double radius() const;
    // The survey's figures: from its parameters always, from its plan when it has one (else why not).
    struct SurveyFigures
    {
        double height = 0, gsdCm = 0, footprintAcross = 0, footprintAlong = 0;  // metres, cm/px
        std::optional<AreaScanPlan> plan;
        QString message;  // why there is no plan
    };
    std::optional<SurveyFigures> figures() const;
    QString figuresText() const;
    QStringList cameras() const;
    QString problem() const { return m_problem; }

    // Sets the parameter of row `index` (typed: a number, a bool, a choice's value, text).
    Q_INVOKABLE bool set(int index, const QVariant &value,
                         sortie::mission::MissionEnums::EditStep step = sortie::mission::MissionEnums::EditStep::Done);
    Q_INVOKABLE bool setRadius(double meters, sortie::mission::MissionEnums::EditStep step = sortie::mission::MissionEnums::EditStep::Done);
    // The index of a parameter by wire name, or -1 (for tests and shortcuts).
    Q_INVOKABLE int indexOf(const QString &name) const;

signals:
    void rowChanged();
    void valuesChanged();

private:
    struct Field
    {
        QString name;
        ParameterDefinition definition;  // synthesised for raw values and Sortie's own names
        bool known = true;
        bool choicesSuggested = false;  // Sortie's list, not the server's: another value is allowed
    };
    void rebuild();
    void refreshValues();
    const Segment *segment() const;

    QPointer<RouteModel> m_model;
    QPointer<RouteEditor> m_editor;
    int m_row = -1;
    std::vector<Field> m_fields;
    QString m_problem;
};

} // namespace sortie::mission
