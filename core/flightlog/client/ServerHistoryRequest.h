#pragma once

#include "ServerHistory.h"

#include <QObject>
#include <QPointer>
#include <QStringList>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace sortie::client {
class VehicleFleet;
}

namespace sortie::flightlog {

class ReplayController;

// What the operator asks of the connected server's telemetry history: which of its vehicles and which
// time range (UTC; the last hour unless changed), checked before anything is sent; then the paged
// fetch (ServerHistory) with progress and cancel, and the result opened in the replay. The server
// history dialog is a view of this object.
class ServerHistoryRequest : public QObject
{
    Q_OBJECT
    Q_PROPERTY(QStringList vehicles READ vehicleNames NOTIFY vehiclesChanged)
    Q_PROPERTY(int vehicleIndex READ vehicleIndex WRITE setVehicleIndex NOTIFY choiceChanged)
    Q_PROPERTY(QString fromText READ fromText WRITE setFromText NOTIFY choiceChanged)
    Q_PROPERTY(QString toText READ toText WRITE setToText NOTIFY choiceChanged)
    Q_PROPERTY(QString problem READ problem NOTIFY choiceChanged)
    Q_PROPERTY(bool canFetch READ canFetch NOTIFY choiceChanged)
    Q_PROPERTY(bool busy READ isBusy NOTIFY busyChanged)
    Q_PROPERTY(double progress READ progress NOTIFY progressChanged)
    Q_PROPERTY(QString errorString READ errorString NOTIFY errorChanged)

public:
    struct ServerVehicle
    {
        QString name;
        int objectId = 0; // the server's Vehicle object id
    };
    static constexpr qint64 kDefaultSpanMs = 60 * 60 * 1000;
    // The history is held in memory while it arrives; a day of 10 Hz telemetry is about 350 MB.
    static constexpr qint64 kLongestSpanMs = 24 * 60 * 60 * 1000;

    ServerHistoryRequest(hci::HciClient *client, ReplayController *replay, QObject *parent = nullptr);

    // Where reset() finds the server's vehicles (its HCI rows); none: setVehicles() only.
    void setFleet(client::VehicleFleet *fleet);
    client::VehicleFleet *fleet() const;
    // Milliseconds since the epoch; the wall clock unless a test sets one.
    void setClock(std::function<qint64()> clock) { m_clock = std::move(clock); }

    // The server's vehicles as the fleet has them now, the same vehicle chosen if it is still there
    // (else the first), the last hour up to now, no error. The dialog calls it each time it opens.
    Q_INVOKABLE void reset();
    Q_INVOKABLE void chooseLastHour();
    void setVehicles(std::vector<ServerVehicle> vehicles);

    QStringList vehicleNames() const;
    int vehicleIndex() const { return m_vehicleIndex; }
    void setVehicleIndex(int index);
    QString fromText() const { return m_fromText; }
    void setFromText(const QString &text);
    QString toText() const { return m_toText; }
    void setToText(const QString &text);

    // Why the choice cannot be fetched, for the operator; empty when it can.
    QString problem() const;
    bool canFetch() const { return problem().isEmpty(); }
    // The chosen range in ms since the epoch, when the texts are times.
    std::optional<std::pair<qint64, qint64>> range() const;
    static QString timeText(qint64 ms);
    static std::optional<qint64> parseTime(const QString &text);

    // Starts the fetch; false (and the reason in problem()) when the choice is not fetchable.
    Q_INVOKABLE bool fetch();
    Q_INVOKABLE void cancel();
    bool isBusy() const { return m_history.isBusy(); }
    double progress() const { return m_history.progress(); }
    QString errorString() const { return m_error; }

signals:
    void vehiclesChanged();
    void choiceChanged();
    void busyChanged();
    void progressChanged();
    void errorChanged();
    void opened(); // the history is in the replay

private:
    void onFinished(bool ok);
    void setError(const QString &error);

    ServerHistory m_history;
    QPointer<ReplayController> m_replay;
    QPointer<client::VehicleFleet> m_fleet;
    std::function<qint64()> m_clock;
    std::vector<ServerVehicle> m_vehicles;
    int m_vehicleIndex = -1;
    QString m_fromText, m_toText;
    QString m_fetching; // the vehicle's name while a fetch runs
    QString m_error;
};

} // namespace sortie::flightlog
