#pragma once

#include "VehicleTypes.h"

#include <QAbstractListModel>
#include <QDateTime>

#include <deque>

namespace sortie::vehicle {

// What was asked of the vehicles and what they answered: every command and upload, with the vehicle,
// and the alerts raised about them (a predicted loss of separation: `alert`),
// the time it was sent and the time and text of its result, newest last. Each entry is also written
// to the sortie.vehicle logging category. A list model for the UI's command log view; `recorded`
// and `finished` let a recorder (the flight log) follow it without polling. Holds the last
// `capacity` entries.
class CommandLog : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ count NOTIFY countChanged)

public:
    enum class Status { Pending, Done, Failed, Cancelled, Alert };
    Q_ENUM(Status)

    struct Entry
    {
        int id = 0;
        QDateTime sent;
        QDateTime answered; // invalid while pending
        QString vehicle;    // the vehicle's name as the operator knows it
        QString command;    // "arm", "takeoff to 20 m", "upload 12 waypoints"
        Status status = Status::Pending;
        QString result;     // the vehicle's or the link's words when it failed
    };

    enum Roles { TimeRole = Qt::UserRole + 1, TimeTextRole, VehicleRole, CommandRole, StatusRole, StatusTextRole, ResultRole, TextRole, FailedRole };

    explicit CommandLog(QObject *parent = nullptr, int capacity = 1000);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

    int count() const { return int(m_entries.size()); }
    const Entry &at(int row) const { return m_entries[size_t(row)]; }
    // The entry with that id, or nullptr when it has aged out.
    const Entry *find(int id) const;

    // A command was sent; returns its id for finish().
    int begin(const QString &vehicle, const QString &command);
    void finish(int id, const CommandResult &result);
    // An alert about a vehicle, not a command: recorded and finished at once (Status::Alert), so the
    // view shows it with the commands and a recorder following `finished` keeps it.
    int alert(const QString &vehicle, const QString &text);
    // begin() now and finish() when the returned callback runs (at most once).
    std::function<void(const CommandResult &)> track(const QString &vehicle, const QString &command);

    static QString statusText(Status status);

signals:
    void countChanged();
    void recorded(const sortie::vehicle::CommandLog::Entry &entry);
    void finished(const sortie::vehicle::CommandLog::Entry &entry);

private:
    int rowOf(int id) const;
    Entry &append(const QString &vehicle, const QString &command);

    std::deque<Entry> m_entries;
    int m_capacity;
    int m_nextId = 1;
};

} // namespace sortie::vehicle
Q_DECLARE_METATYPE(sortie::vehicle::CommandLog::Entry)
