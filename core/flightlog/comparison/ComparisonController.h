#pragma once

#include "RouteComparison.h"

#include <QAbstractListModel>
#include <QObject>
#include <QPointer>

namespace sortie::flightlog {

class ReplayController;

// How far a deviation is from the plan, for colours and the table: within kDeviationFine metres is
// fine (0), within kDeviationWarn a warning (1), beyond it bad (2).
inline constexpr double kDeviationFine = 2.0, kDeviationWarn = 5.0;
int deviationLevel(double metres);

// The legs of a comparison as table rows.
class ComparisonLegModel : public QAbstractListModel
{
    Q_OBJECT
public:
    enum Roles { LegRole = Qt::UserRole + 1, SamplesRole, MaxCrossTrackRole, MeanCrossTrackRole, MaxAltitudeRole,
                 MeanAltitudeRole, ReachedRole, LevelRole };
    explicit ComparisonLegModel(QObject *parent = nullptr); // its rows are worded as read: re-read on a language change
    void reset(const RouteComparison *comparison);
    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

private:
    const RouteComparison *m_c = nullptr;
};

// The compared track, point by point with its cross-track deviation: the map's coloured overlay.
class ComparisonTrackModel : public QAbstractListModel
{
    Q_OBJECT
public:
    enum Roles { LatitudeRole = Qt::UserRole + 1, LongitudeRole, DeviationRole, LevelRole };
    using QAbstractListModel::QAbstractListModel;
    void reset(const RouteComparison *comparison);
    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

private:
    const RouteComparison *m_c = nullptr;
};

// The comparison in the UI: the replayed log's vehicle against a route file, as a table of legs,
// a coloured track for the map, and a summary line; or why the route was refused.
class ComparisonController : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool available READ isAvailable NOTIFY changed)
    Q_PROPERTY(QString summary READ summary NOTIFY changed)
    Q_PROPERTY(QString errorString READ errorString NOTIFY changed)
    Q_PROPERTY(QAbstractListModel *legs READ legs CONSTANT)
    Q_PROPERTY(QAbstractListModel *track READ track CONSTANT)

public:
    explicit ComparisonController(ReplayController *replay, QObject *parent = nullptr);

    // Compares the replayed vehicle in `vehicleRow` (-1: the only one) with the first route of a
    // file (path or file: URL).
    Q_INVOKABLE bool compare(const QString &routeFile, int vehicleRow);
    Q_INVOKABLE void clear();

    bool isAvailable() const { return m_result.has_value(); }
    QString summary() const;
    QString errorString() const { return m_error; }
    QAbstractListModel *legs() { return &m_legs; }
    QAbstractListModel *track() { return &m_track; }
    const std::optional<RouteComparison> &result() const { return m_result; }

signals:
    void changed();

private:
    QPointer<ReplayController> m_replay;
    std::optional<RouteComparison> m_result;
    QString m_error;
    ComparisonLegModel m_legs;
    ComparisonTrackModel m_track;
};

} // namespace sortie::flightlog
