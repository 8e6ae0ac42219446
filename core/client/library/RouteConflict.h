#pragma once

#include "RouteModel.h"

#include <QObject>
#include <QStringList>

#include <memory>

namespace com::ugcs::ucs::proto { class Route; }

namespace sortie::client {

// The server's copy of the open route when someone else saved it meanwhile, for the operator to
// compare with theirs before choosing: how the two differ (RouteDiff theirs → mine), what each side
// changed since the version both started from, the version numbers, and their route as a read-only
// model for a ghost layer on the map.
class RouteConflict : public QObject
{
    Q_OBJECT
    Q_PROPERTY(bool active READ isActive NOTIFY changed)
    Q_PROPERTY(QStringList changes READ changes NOTIFY changed)
    Q_PROPERTY(QStringList yourEdits READ yourEdits NOTIFY changed)
    Q_PROPERTY(QStringList theirEdits READ theirEdits NOTIFY changed)
    Q_PROPERTY(int yourVersion READ yourVersion NOTIFY changed)
    Q_PROPERTY(int theirVersion READ theirVersion NOTIFY changed)
    Q_PROPERTY(QDateTime theirSaveTime READ theirSaveTime NOTIFY changed)
    Q_PROPERTY(sortie::mission::RouteModel *theirs READ theirModel CONSTANT)

public:
    explicit RouteConflict(QObject *parent = nullptr);
    ~RouteConflict() override;

    // `theirs` as the server sent it, `mine` the document's route, `common` the route as it was
    // opened (what both sides edited). False (and inactive) when theirs cannot be read as a route.
    bool set(const com::ugcs::ucs::proto::Route &theirs, const mission::Route &mine, const mission::Route &common);
    void clear();

    bool isActive() const { return bool(m_theirs); }
    const com::ugcs::ucs::proto::Route *theirMessage() const { return m_theirs.get(); }
    const mission::Route &theirRoute() const { return m_model.route(); }
    QStringList changes() const { return m_changes; }
    QStringList yourEdits() const { return m_yourEdits; }
    QStringList theirEdits() const { return m_theirEdits; }
    int yourVersion() const { return m_yourVersion; }
    int theirVersion() const;
    QDateTime theirSaveTime() const;
    mission::RouteModel *theirModel() { return &m_model; }

signals:
    void changed();

private:
    std::unique_ptr<com::ugcs::ucs::proto::Route> m_theirs;
    mission::RouteModel m_model;
    QStringList m_changes;
    QStringList m_yourEdits;
    QStringList m_theirEdits;
    int m_yourVersion = -1;
};

} // namespace sortie::client
