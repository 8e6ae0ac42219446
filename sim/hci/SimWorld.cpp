#include "SimWorld.h"

#include "Messages.pb.h"
#include "SimDemoContent.h"
#include "SimZones.h"
#include "SimDjiProfiles.h"
#include "SimLog.h"
#include "SimStoreFile.h"
#include "SimTerrain.h"
#include "SimVehicle.h"

#include <QDateTime>
#include <QFileInfo>

namespace sortie::sim {

SimWorld::SimWorld(QObject *parent)
    : SimWorld(Config{}, parent)
{
}

SimWorld::SimWorld(Config config, QObject *parent)
    : QObject(parent)
    , m_config(std::move(config))
    , m_users(m_config.users.isEmpty() ? SimUsers() : SimUsers(m_config.users))
    , m_terrain(std::make_unique<SimTerrain>(m_config.groundElevation))
    , m_traffic(m_config.mannedTraffic)
{
    m_ticker.setTimerType(Qt::PreciseTimer);
    connect(&m_ticker, &QTimer::timeout, this, &SimWorld::tick);
    m_saveTimer.setSingleShot(true);
    m_saveTimer.setInterval(300);
    connect(&m_saveTimer, &QTimer::timeout, this, [this] {
        QString error;
        if (!saveStore(&error))
            qCWarning(lcSim).noquote() << "cannot save the store:" << error;
    });
}

SimWorld::~SimWorld()
{
    if (m_saveTimer.isActive())
        saveStore();
}

qint64 SimWorld::now()
{
    return QDateTime::currentMSecsSinceEpoch();
}

bool SimWorld::start(QString *error)
{
    if (m_started)
        return true;
    if (!m_config.storePath.isEmpty() && QFileInfo::exists(m_config.storePath)) {
        if (!SimStoreFile::load(m_config.storePath, m_store, error))
            return false;
        qCInfo(lcSim).noquote() << "loaded" << m_store.count() << "objects from" << m_config.storePath;
        m_routePasses.clearStale();
    }
    if (!m_config.demPath.isEmpty()) {
        QString demError;
        auto dem = SimTerrain::fromDem(m_config.demPath, &demError);
        if (!dem) {
            if (error)
                *error = demError;
            return false;
        }
        m_terrain = std::move(dem);
    }
    qCInfo(lcSim).noquote() << "ground from" << m_terrain->description();
    const QList<int> ids = SimDemoContent::seed(m_store, m_users, m_config.vehicles, m_config.groundElevation,
                                                m_config.demoMission, now());
    SimDjiProfiles::seed(m_store, now());
    SimZones::seed(m_store, m_config.demoMission, now());
    const auto homes = SimDemoContent::vehicleHomes(m_config.vehicles);
    for (int i = 0; i < ids.size(); ++i) {
        const auto *object = m_store.find(QStringLiteral("Vehicle"), ids[i]);
        const double homeGround = m_terrain->groundOr(homes[i].latitude, homes[i].longitude, m_config.groundElevation);
        FlightModel model(homes[i].latitude, homes[i].longitude, homeGround, FlightModel::Limits::forProfile(m_config.energy));
        m_vehicles.push_back(std::make_unique<SimVehicle>(object->vehicle(), std::move(model), m_config.telemetryRateHz));
        m_vehicles.back()->setTerrain(m_terrain.get());
    }
    connect(&m_store, &SimObjectStore::changed, this,
            [this](int type, const QString &objectType, int id, const pb::DomainObjectWrapper &object) {
                if (objectType == QLatin1String("Vehicle") && type == pb::MT_UPDATE)
                    if (SimVehicle *v = vehicle(id))
                        v->setVehicle(object.vehicle());
            });
    if (!m_config.storePath.isEmpty()) {
        connect(&m_store, &SimObjectStore::changed, this, [this] { m_saveTimer.start(); });
        saveStore();
    }
    m_started = true;
    m_clock.start();
    m_lastTickNs = 0;
    setTelemetryRate(m_config.telemetryRateHz);
    return true;
}

void SimWorld::setTelemetryRate(double hz)
{
    m_config.telemetryRateHz = hz;
    if (hz <= 0) {
        m_ticker.stop();
        return;
    }
    m_ticker.start(std::max(1, int(1000.0 / hz)));
}

bool SimWorld::saveStore(QString *error)
{
    m_saveTimer.stop();
    if (m_config.storePath.isEmpty())
        return true;
    return SimStoreFile::save(m_config.storePath, m_store, error);
}

SimVehicle *SimWorld::vehicle(int id) const
{
    for (const auto &v : m_vehicles)
        if (v->id() == id)
            return v.get();
    return nullptr;
}

std::vector<pb::CommandDefinition> SimWorld::commandDefinitions() const
{
    std::vector<pb::CommandDefinition> all;
    for (const auto &v : m_vehicles)
        for (auto &d : v->commands())
            all.push_back(std::move(d));
    return all;
}

void SimWorld::tick()
{
    // Integrate over the real elapsed time, so a late timer does not slow the vehicles down.
    const qint64 nowNs = m_clock.nsecsElapsed();
    const double dt = std::clamp((nowNs - m_lastTickNs) / 1e9, 0.001, 1.0);
    m_lastTickNs = nowNs;
    const qint64 time = now();
    for (const auto &v : m_vehicles) {
        pb::TelemetryEvent event;
        const bool commandsChanged = v->tick(dt, time, &event);
        emit telemetry(event);
        m_routePasses.follow(*v);
        if (commandsChanged)
            emit this->commandsChanged(v->id());
    }
}

} // namespace sortie::sim
