#pragma once

#include "FlightLog.h"

#include <QAbstractListModel>

namespace sortie::flightlog {

// The events of a log the timeline can jump to (arming, mode changes, commands, uploads, link
// changes), with where each sits on the timeline (0..1), for a list and for marks on the bar.
class ReplayEventModel : public QAbstractListModel
{
    Q_OBJECT
    Q_PROPERTY(int count READ rowCount NOTIFY countChanged)

public:
    enum Roles { TimeRole = Qt::UserRole + 1, TimeTextRole, KindRole, TextRole, VehicleRole, FractionRole, FailedRole };

    using QAbstractListModel::QAbstractListModel;

    void reset(const FlightLog *log);
    const FlightLog::Event *eventAt(int row) const;
    // The first event after / last event before a time; -1 when none.
    int nextAfter(int64_t time) const;
    int lastBefore(int64_t time) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

signals:
    void countChanged();

private:
    const FlightLog *m_log = nullptr;
    std::vector<const FlightLog::Event *> m_events; // the ones worth jumping to
};

} // namespace sortie::flightlog
