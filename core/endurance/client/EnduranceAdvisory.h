#pragma once

#include "EnduranceEstimate.h"
#include "FlightAlerts.h"
#include "RouteEndurance.h"  // a property's type: moc needs it whole

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>
#include <QVariant>

namespace sortie::vehicle {
class Vehicle;
}

namespace sortie::endurance {


// In flight, for one vehicle: will its battery bring it home? With the energy profile and wind in
// use (the RouteEndurance's), from the vehicle's battery, position, height and home:
//   energyLeftWh  = remaining × batteryWh
//   energyHomeWh  = straight home at cruise speed in the wind, then down to home (energyHomeWh())
//   margin        = energyLeftWh − energyHomeWh − reserve × batteryWh
//   batteryAtEnd  = what is left after the rest of the on-board mission (a Route built from the
//                   position and the items from missionCurrent on, priced by estimateEndurance)
// and a level: Red when margin ≤ 0, Amber when margin ≤ amberBand × batteryWh, Normal above, Unknown
// when an input is missing (no profile, no battery figure, no home, no position): missing, never 0.
// Amber and Red are an in-flight alert (the contract of vehicle::AlertModel, as the zone and
// proximity alerts): one row with the advice, the fly view's banner shows it. Each escalation while
// armed (Normal → Amber, → Red) writes one alert line to the vehicle's command log; the level only
// falls back once the margin has cleared its threshold by `hysteresis` × batteryWh, so a margin
// wobbling on a threshold neither flaps nor repeats the line. Recomputed at most every `interval` ms
// however fast telemetry comes (docs/endurance.md, "In flight").
class EnduranceAdvisory : public vehicle::AlertList<vehicle::FlightAlert>
{
    Q_OBJECT
    Q_PROPERTY(QObject *vehicle READ vehicleObject WRITE setVehicle NOTIFY vehicleChanged)
    Q_PROPERTY(sortie::endurance::RouteEndurance *endurance READ endurance WRITE setEndurance NOTIFY enduranceChanged)
    Q_PROPERTY(Level level READ level NOTIFY changed)
    Q_PROPERTY(QVariant energyLeftWh READ energyLeftWh NOTIFY changed)   // Wh; undefined when missing
    Q_PROPERTY(QVariant energyHomeWh READ energyHomeWh NOTIFY changed)   // Wh
    Q_PROPERTY(QVariant reserveWh READ reserveWh NOTIFY changed)         // Wh
    Q_PROPERTY(QVariant margin READ margin NOTIFY changed)               // Wh: left − home − reserve
    Q_PROPERTY(QVariant batteryAtEnd READ batteryAtEnd NOTIFY changed)   // fraction of the battery after the mission
    Q_PROPERTY(QString problem READ problem NOTIFY changed)              // why the level is Unknown / a figure missing
    Q_PROPERTY(QString summary READ summary NOTIFY changed)              // "Battery at end of route: 34 % · home needs 12 Wh"
    Q_PROPERTY(QString advice READ advice NOTIFY changed)                // the banner's words; empty when Normal or Unknown
    Q_PROPERTY(QString returnHomeQuestion READ returnHomeQuestion NOTIFY changed)
    Q_PROPERTY(double amberBand READ amberBand WRITE setAmberBand NOTIFY thresholdsChanged)   // fraction of batteryWh
    Q_PROPERTY(double hysteresis READ hysteresis WRITE setHysteresis NOTIFY thresholdsChanged) // fraction of batteryWh
    Q_PROPERTY(int interval READ interval WRITE setInterval NOTIFY thresholdsChanged)          // ms between updates

public:
    enum class Level { Unknown, Normal, Amber, Red };
    Q_ENUM(Level)

    explicit EnduranceAdvisory(QObject *parent = nullptr);
    ~EnduranceAdvisory() override;

    vehicle::Vehicle *vehicle() const;
    QObject *vehicleObject() const;
    void setVehicle(QObject *vehicle);
    RouteEndurance *endurance() const;
    void setEndurance(RouteEndurance *endurance);

    Level level() const { return m_level; }
    QVariant energyLeftWh() const { return optional(m_left); }
    QVariant energyHomeWh() const { return optional(m_home); }
    QVariant reserveWh() const { return optional(m_reserve); }
    QVariant margin() const { return optional(m_margin); }
    QVariant batteryAtEnd() const { return optional(m_batteryAtEnd); }
    QString problem() const { return m_problem; }
    QString summary() const;
    QString advice() const;
    QString returnHomeQuestion() const;

    double amberBand() const { return m_amberBand; }
    void setAmberBand(double fraction);
    double hysteresis() const { return m_hysteresis; }
    void setHysteresis(double fraction);
    int interval() const { return m_interval; }
    void setInterval(int ms);

    // The level a margin is at, given the level it was at: escalates at once, falls back only
    // past threshold + hysteresis. `band` and `hysteresis` in Wh.
    static Level judge(double margin, double band, double hysteresis, Level previous);

public slots:
    // Recomputes now, whatever the throttle (the throttle calls it).
    void refresh();

signals:
    void vehicleChanged();
    void enduranceChanged();
    void changed();
    void thresholdsChanged();
    // The level rose (Normal → Amber, → Red) while the vehicle flew; the log line was written.
    void escalated(sortie::endurance::EnduranceAdvisory::Level level);

private:
    static QVariant optional(const std::optional<double> &v) { return v ? QVariant(*v) : QVariant(); }
    void schedule();
    void clear(const QString &problem);
    // The banner's row for the level now; `news`: an escalation the command log is told of.
    void publishAdvice(bool news);

    QPointer<vehicle::Vehicle> m_vehicle;
    QPointer<RouteEndurance> m_endurance;
    Level m_level = Level::Unknown;
    Level m_logged = Level::Normal;  // the highest level logged since the level was last Normal
    std::optional<double> m_left, m_home, m_reserve, m_margin, m_batteryAtEnd;
    QString m_problem;
    double m_amberBand = 0.10;
    double m_hysteresis = 0.02;
    int m_interval = 250;
    QTimer m_throttle;
    bool m_pending = false;
};

} // namespace sortie::endurance
