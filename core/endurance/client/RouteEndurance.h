#pragma once

#include "EnduranceEstimate.h"

#include <QObject>
#include <QPointer>
#include <QUrl>
#include <QVariant>

#include <memory>
#include <optional>

class QSettings;

namespace sortie::mission {
class RouteAnalyzer;
class RouteModel;
} // namespace sortie::mission

namespace sortie::endurance {

class EnduranceRule;

// The endurance of the open route, for the views: which energy profile applies (a JSON file the
// operator chose, remembered in the settings), and for the route as the analyzer last saw it the
// flight time, energy, battery at the end, batteries needed, battery changes and the point of no
// return. Without a profile (or when the route cannot be flown) every figure is undefined, never 0:
// `missing` says so and `problem` says why. It registers the endurance rule on the analyzer, so
// validation and the upload gate see the same estimate.
//
// The UgCS server's vehicle profile carries no powers or battery energy (only VPT_MAX_FLIGHT_TIME,
// voltages and weights), so a server profile is not a source here (docs/endurance.md).
class RouteEndurance : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool missing READ isMissing NOTIFY estimateChanged)
    Q_PROPERTY(QString problem READ problem NOTIFY estimateChanged)
    Q_PROPERTY(QString profileName READ profileName NOTIFY profileChanged)
    Q_PROPERTY(QString profileSource READ profileSource NOTIFY profileChanged)  // "file", "fit"; "" without one
    Q_PROPERTY(QString profilePath READ profilePath NOTIFY profileChanged)
    Q_PROPERTY(QVariant reserve READ reserve NOTIFY profileChanged)             // fraction kept at landing
    Q_PROPERTY(QVariant flightTime READ flightTime NOTIFY estimateChanged)      // seconds
    Q_PROPERTY(QVariant energyWh READ energyWh NOTIFY estimateChanged)
    Q_PROPERTY(QVariant batteryAtEnd READ batteryAtEnd NOTIFY estimateChanged)  // fraction of one battery, < 0: more needed
    Q_PROPERTY(QVariant batteriesNeeded READ batteriesNeeded NOTIFY estimateChanged)
    // The battery changes the route needs (estimate()->changes has where and whether planned).
    Q_PROPERTY(int changeCount READ changeCount NOTIFY estimateChanged)
    // The point of no return (estimate()->pointOfNoReturn): metres along the flown path and its
    // leg; undefined when there is none or home is unknown.
    Q_PROPERTY(QVariant noReturnDistance READ noReturnDistance NOTIFY estimateChanged)
    Q_PROPERTY(QVariant noReturnLeg READ noReturnLeg NOTIFY estimateChanged)
    Q_PROPERTY(bool homeKnown READ homeKnown NOTIFY estimateChanged)
    Q_PROPERTY(double windSpeed READ windSpeed WRITE setWindSpeed NOTIFY conditionsChanged)    // m/s
    Q_PROPERTY(double windFrom READ windFrom WRITE setWindFrom NOTIFY conditionsChanged)      // degrees it blows from
    Q_PROPERTY(bool stopAndTurn READ stopAndTurn WRITE setStopAndTurn NOTIFY conditionsChanged)

public:
    // `settings` (not owned) remembers the profile file; `analyzer` and `model` are the open route's.
    RouteEndurance(QSettings *settings, mission::RouteAnalyzer *analyzer, const mission::RouteModel *model, QObject *parent = nullptr);
    ~RouteEndurance() override;

    // Reads a profile file and uses it (remembered); false with `problem` set when it cannot be read.
    Q_INVOKABLE bool loadProfile(const QString &path);
    // The same for a file a dialog chose.
    Q_INVOKABLE bool loadProfileFile(const QUrl &file) { return loadProfile(file.toLocalFile()); }
    Q_INVOKABLE void clearProfile();
    // Energy (Wh) to fly home from a position at a height above home, with the profile and wind in
    // use; undefined without a profile, home or headway. For the fly view's advisory.
    Q_INVOKABLE QVariant energyHomeWh(double latitude, double longitude, double heightAboveHome) const;

    void setProfile(const std::optional<EnergyProfile> &profile, const QString &path = {});
    const std::optional<EnergyProfile> &profile() const { return m_profile; }
    const std::optional<EnduranceEstimate> &estimate() const { return m_estimate; }
    const FlightConditions &conditions() const { return m_conditions; }
    EnduranceRule *rule() const { return m_rule.get(); }

    bool isMissing() const { return !m_estimate.has_value(); }
    QString problem() const { return m_problem; }
    QString profileName() const;
    QString profileSource() const;
    QString profilePath() const { return m_path; }
    QVariant reserve() const;
    QVariant flightTime() const;
    QVariant energyWh() const;
    QVariant batteryAtEnd() const;
    QVariant batteriesNeeded() const;
    int changeCount() const { return m_estimate ? int(m_estimate->changes.size()) : 0; }
    QVariant noReturnDistance() const;
    QVariant noReturnLeg() const;
    bool homeKnown() const { return m_estimate && m_estimate->homeKnown; }
    double windSpeed() const { return m_conditions.wind.speed; }
    double windFrom() const { return m_conditions.wind.fromDeg; }
    bool stopAndTurn() const { return m_conditions.turns == mission::TurnMode::StopAndTurn; }
    void setWindSpeed(double speed);
    void setWindFrom(double degrees);
    void setStopAndTurn(bool on);

    // Recomputes from the route as it is now (the analyzer calls this after each recomputation).
    void refresh();

signals:
    void profileChanged();
    void estimateChanged();
    void conditionsChanged();

private:
    void setConditions(const FlightConditions &conditions);

    QSettings *m_settings;
    QPointer<mission::RouteAnalyzer> m_analyzer;
    const mission::RouteModel *m_model;
    std::unique_ptr<EnduranceRule> m_rule;
    std::optional<EnergyProfile> m_profile;
    QString m_path;
    FlightConditions m_conditions;
    std::optional<EnduranceEstimate> m_estimate;
    std::optional<mission::HomePosition> m_home;
    QString m_problem;
};

} // namespace sortie::endurance
