#pragma once

#include <QAbstractListModel>

#include <algorithm>
#include <functional>
#include <vector>

namespace sortie::vehicle {

class CommandLog;

// What every in-flight alert says, whichever monitor found it (ProximityMonitor, ZoneAlertMonitor,
// EnduranceAdvisory); a monitor's own alert type adds its figures to it.
struct FlightAlert
{
    enum class Severity { Warning, Danger };
    QString key;           // the same alert while its key is, however its figures move
    QString vehicle;       // the vehicle's name, as the command log has it
    QString text;          // what the banner and the command log say
    double inSeconds = 0;  // to the predicted event; 0: it is there now
    Severity severity = Severity::Danger;
};

// The in-flight alert contract: a row per alert, most urgent first (the fly view's AlertBanner
// shows them), each alert written once to the command log when it rises (CommandLog::alert, which
// the flight recorder keeps as an "alert" event) with alertRaised, and alertCleared when it goes.
// A monitor finds its alerts and hands them to AlertList::publish; this class does the rest.
class AlertModel : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(Subject subject READ subject CONSTANT)
    Q_PROPERTY(int count READ count NOTIFY countChanged)
    // The most urgent alert's text; empty without one.
    Q_PROPERTY(QString headline READ headline NOTIFY countChanged)

public:
    // What the alerts are about (the banner words them: "Too close", "Airspace", the battery's own).
    enum class Subject { Proximity, Airspace, Battery };
    Q_ENUM(Subject)
    enum Roles { KeyRole = Qt::UserRole + 1, VehicleRole, TextRole, InSecondsRole, WarningRole };

    Subject subject() const { return m_subject; }
    int count() const { return alertCount(); }
    QString headline() const { return count() > 0 ? alertAt(0).text : QString(); }
    const FlightAlert &alertAt(int row) const { return alertRow(row); }

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void countChanged();
    // The alert rose and was written to the command log.
    void alertRaised(const QString &key);
    void alertCleared(const QString &key);

protected:
    AlertModel(Subject subject, QObject *parent);
    virtual int alertCount() const = 0;
    virtual const FlightAlert &alertRow(int row) const = 0;
    // After the rows were replaced: writes each of `announced` to `log` (may be null) and signals.
    void announce(const std::vector<const FlightAlert *> &announced, const std::vector<QString> &cleared, bool rowsChanged,
                  CommandLog *log);

private:
    Subject m_subject;
};

// The rows of one monitor's alert type (a FlightAlert or a type derived from it).
template<class Alert>
class AlertList : public AlertModel
{
public:
    const std::vector<Alert> &alerts() const { return m_alerts; }

protected:
    using AlertModel::AlertModel;

    // The alerts found now, most urgent first. An alert whose key was not there before rose; it is
    // logged unless `isNews` (when given) says it is no news (the battery's fall from red to amber).
    void publish(std::vector<Alert> now, CommandLog *log, const std::function<bool(const Alert &)> &isNews = {})
    {
        if (now.empty() && m_alerts.empty())
            return;  // a quiet sky: the banner's rows are not reset (nothing to draw again)
        const auto has = [](const std::vector<Alert> &list, const QString &key) {
            return std::any_of(list.begin(), list.end(), [&key](const Alert &a) { return a.key == key; });
        };
        std::vector<QString> cleared;
        for (const Alert &old : m_alerts)
            if (!has(now, old.key))
                cleared.push_back(old.key);
        std::vector<bool> raised;
        for (const Alert &a : now)
            raised.push_back(!has(m_alerts, a.key) && (!isNews || isNews(a)));
        const bool rowsChanged = now.size() != m_alerts.size() || std::find(raised.begin(), raised.end(), true) != raised.end()
                                 || (!now.empty() && now.front().text != m_alerts.front().text);
        beginResetModel();
        m_alerts = std::move(now);
        endResetModel();
        std::vector<const FlightAlert *> announced;
        for (size_t i = 0; i < m_alerts.size(); ++i)
            if (raised[i])
                announced.push_back(&m_alerts[i]);
        announce(announced, cleared, rowsChanged, log);
    }

private:
    int alertCount() const override { return int(m_alerts.size()); }
    const FlightAlert &alertRow(int row) const override { return m_alerts[size_t(row)]; }

    std::vector<Alert> m_alerts;
};

} // namespace sortie::vehicle
