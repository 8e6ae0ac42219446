#pragma once

#include "Checklist.h"
#include "PreflightVerdict.h"

#include <QAbstractListModel>
#include <QPointer>

#include <functional>
#include <vector>

namespace sortie::vehicle {
class Vehicle;
}

namespace sortie::preflight {

// One vehicle's pre-flight checklist as the fly view shows it: one row per item, its verdict from
// the facts (handed in as a function, so this model knows no fleet or route) and the operator's
// ticks. The verdicts follow the vehicle (its telemetry, link and camera) and whatever the owner
// says changed (refresh()); a row is signalled only when what it shows changed. The ticks hold
// until the vehicle lands from the flight they were made for: disarmed after having been armed,
// every tick is cleared, so the next flight is checked again.
class VehicleChecklist : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(QString name READ name CONSTANT)
    Q_PROPERTY(QString source READ source CONSTANT)          // the file read, or "" for Sortie's default
    Q_PROPERTY(QString sourceError READ sourceError CONSTANT) // why the file was not used; "" when it was
    Q_PROPERTY(int count READ count CONSTANT)
    Q_PROPERTY(bool readyToArm READ readyToArm NOTIFY verdictsChanged)
    Q_PROPERTY(bool readyForAuto READ readyForAuto NOTIFY verdictsChanged)
    Q_PROPERTY(int passedCount READ passedCount NOTIFY verdictsChanged)
    // Items that hold back Arm or Auto now: what the operator still has to do.
    Q_PROPERTY(int holdingCount READ holdingCount NOTIFY verdictsChanged)

public:
    enum Roles { TitleRole = Qt::UserRole + 1, DetailRole, OutcomeRole, RequiredRole, ManualRole, TickedRole, HoldsBackRole };
    // The outcome role, in QML: VehicleChecklist.Pass, … (preflight::Outcome's values).
    enum Shown { Pass = int(Outcome::Pass), Fail = int(Outcome::Fail), Missing = int(Outcome::Missing),
                 Ticked = int(Outcome::Ticked), Unticked = int(Outcome::Unticked), NotReported = int(Outcome::NotReported) };
    Q_ENUM(Shown)

    using FactsFunction = std::function<PreflightFacts(const vehicle::Vehicle *)>;

    VehicleChecklist(vehicle::Vehicle *vehicle, Checklist checklist, QString source, QString sourceError, FactsFunction facts,
                     QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

    QString name() const { return m_checklist.name; }
    QString source() const { return m_source; }
    QString sourceError() const { return m_sourceError; }
    int count() const { return int(m_checklist.items.size()); }
    bool readyToArm() const { return blockers(GateArm).isEmpty(); }
    bool readyForAuto() const { return blockers(GateAuto).isEmpty(); }
    int passedCount() const;
    int holdingCount() const;
    vehicle::Vehicle *vehicle() const { return m_vehicle; }

    // An item to tick ticked or not; false for a row that is not one.
    Q_INVOKABLE bool setTicked(int row, bool ticked);
    // One line per item that holds back a command of the gate: "GPS fix: 2D (3D needed)".
    QStringList blockers(Gate gate) const;
    // The verdicts again, from fresh facts.
    void refresh();

    // The item's name: the file's title, else the program's name of its check.
    static QString titleOf(const ChecklistItem &item);
    // What the verdict says, in the operator's words ("6 of 8 satellites", "not reported").
    static QString detailOf(const ChecklistItem &item, const ItemVerdict &verdict);

signals:
    void verdictsChanged();

private:
    void watchArming();

    QPointer<vehicle::Vehicle> m_vehicle;
    Checklist m_checklist;
    QString m_source, m_sourceError;
    FactsFunction m_facts;
    std::vector<bool> m_ticked;
    std::vector<ItemVerdict> m_verdicts;
    bool m_wasArmed = false;
};

} // namespace sortie::preflight
