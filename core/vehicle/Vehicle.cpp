#include "Vehicle.h"

#include "CommandLog.h"
#include "LanguageChange.h"

#include <cmath>
#include <QCoreApplication>

namespace sortie::vehicle {

namespace {
// Equal values, NaN (a value the vehicle does not have) equal to NaN.
bool sameValue(double a, double b)
{
    return a == b || (std::isnan(a) && std::isnan(b));
}
} // namespace

Vehicle::Vehicle(VehicleLink *link, QObject *parent, size_t historyCapacity)
    : QObject(parent)
    , m_link(link)
    , m_protocol(link ? link->protocol() : QString())
    , m_identity(link ? link->identity() : VehicleIdentity{})
    , m_history(historyCapacity)
{
    m_staleFields.set();
    m_clock.start();
    m_notifyTimer.setSingleShot(true);
    connect(&m_notifyTimer, &QTimer::timeout, this, &Vehicle::emitNotify);
    connect(&m_staleTimer, &QTimer::timeout, this, &Vehicle::checkStale);
    // The views format its numbers in the language's locale: after a change they read them again
    // (a parked vehicle's values do not change, so nothing else would). Queued: the locale is set
    // after the translators, whose change is announced at once.
    i18n::onLanguageChange(this, [this] {
        QMetaObject::invokeMethod(this, [this] { emit telemetryChanged(); }, Qt::QueuedConnection);
    });
    m_staleTimer.start(std::min(1000, m_staleAfter / 2));
    if (!link)
        return;
    connect(link, &VehicleLink::telemetryReceived, this, &Vehicle::ingest);
    connect(link, &VehicleLink::stateChanged, this, [this](VehicleLink::State state) {
        if (state == VehicleLink::State::Connected && !m_lastError.isEmpty()) {
            m_lastError.clear();
            emit lastErrorChanged();
        }
        if (state == VehicleLink::State::Connected)
            readParameters();
        emit linkStateChanged();
    });
    connect(link, &VehicleLink::errorOccurred, this, [this](const QString &message) {
        if (message == m_lastError)
            return;
        m_lastError = message;
        emit lastErrorChanged();
    });
    // What the vehicle reports on its own (a fence breach) goes beside the commands, as an alert.
    connect(link, &VehicleLink::videoStreamUriReported, this, [this](const QString &uri) {
        if (uri == m_videoStreamUri)
            return;
        m_videoStreamUri = uri;
        emit videoStreamUriChanged();
    });
    connect(link, &VehicleLink::photoTaken, this, [this](const CameraPhoto &photo) {
        m_lastPhoto = photo;
        ++m_photoCount;
        emit photoTaken(photo);
    });
    connect(link, &VehicleLink::alertReported, this, [this](const QString &text) {
        if (m_commandLog)
            m_commandLog->alert(name(), text);
    });
    connect(link, &VehicleLink::identityChanged, this, [this](const VehicleIdentity &identity) {
        if (identity == m_identity)
            return;
        m_identity = identity;
        emit identityChanged();
    });
}

void Vehicle::ingest(const TelemetryBatch &batch)
{
    if (batch.empty())
        return;
    const qint64 now = m_clock.elapsed();
    for (const TelemetryUpdate &u : batch) {
        Last &last = m_last[size_t(u.field)];
        if (last.receivedAt < 0 || !sameValue(last.sample.value, u.value))
            m_dirty = true; // a new value, not the same one again with a later time
        last.sample = {u.time, u.value};
        last.receivedAt = now;
        if (m_staleFields.test(size_t(u.field))) {
            m_staleFields.reset(size_t(u.field));
            m_staleDirty = true;
        }
    }
    m_history.ingest(batch);
    m_historyDirty = true;
    m_lastReceivedAt = now;
    if (m_stale) {
        m_stale = false;
        m_staleDirty = true;
    }
    scheduleNotify();
}

void Vehicle::replaceHistory(TelemetryStore history)
{
    m_history = std::move(history);
    m_historyDirty = true; // the plots redraw on historyChanged
    scheduleNotify();
}

void Vehicle::scheduleNotify()
{
    if (!m_dirty && !m_historyDirty && !m_staleDirty)
        return;
    if (m_notifyTimer.isActive())
        return; // already gathering
    const qint64 since = m_clock.elapsed() - m_lastNotifyAt;
    if (since >= m_notifyInterval)
        emitNotify();
    else
        m_notifyTimer.start(int(m_notifyInterval - since));
}

void Vehicle::emitNotify()
{
    m_lastNotifyAt = m_clock.elapsed();
    if (m_staleDirty) {
        m_staleDirty = false;
        emit staleChanged();
    }
    if (m_dirty) {
        m_dirty = false;
        ++m_notifications;
        emit telemetryChanged();
    }
    if (m_historyDirty) {
        m_historyDirty = false;
        emit historyChanged();
    }
}

void Vehicle::checkStale()
{
    const qint64 now = m_clock.elapsed();
    bool changed = false;
    for (size_t i = 0; i < kTelemetryFieldCount; ++i) {
        const bool stale = m_last[i].receivedAt < 0 || now - m_last[i].receivedAt > m_staleAfter;
        if (stale != m_staleFields.test(i)) {
            m_staleFields.set(i, stale);
            changed = true;
        }
    }
    const bool stale = m_lastReceivedAt < 0 || now - m_lastReceivedAt > m_staleAfter;
    if (stale != m_stale) {
        m_stale = stale;
        changed = true;
    }
    if (changed)
        emit staleChanged();
}

void Vehicle::setNotifyInterval(int ms)
{
    ms = std::max(0, ms);
    if (ms == m_notifyInterval)
        return;
    m_notifyInterval = ms;
    emit notifyIntervalChanged();
}

void Vehicle::setStaleAfter(int ms)
{
    m_staleAfter = std::max(1, ms);
    m_staleTimer.start(std::clamp(m_staleAfter / 2, 1, 1000));
}

void Vehicle::setMission(std::vector<MissionItem> items)
{
    if (items == m_mission)
        return;
    m_mission = std::move(items);
    emit missionChanged();
}

std::optional<TelemetrySample> Vehicle::last(TelemetryField field) const
{
    const Last &l = m_last[size_t(field)];
    if (l.receivedAt < 0)
        return std::nullopt;
    return l.sample;
}

double Vehicle::value(TelemetryField field, double fallback) const
{
    const Last &l = m_last[size_t(field)];
    return l.receivedAt < 0 ? fallback : l.sample.value;
}

bool Vehicle::isStale(TelemetryField field) const
{
    const Last &l = m_last[size_t(field)];
    return l.receivedAt < 0 || m_clock.elapsed() - l.receivedAt > m_staleAfter;
}

double Vehicle::value(const QString &field) const
{
    const auto f = fieldFromName(field.toStdString());
    return f ? value(*f) : qQNaN();
}

bool Vehicle::isFieldStale(const QString &field) const
{
    const auto f = fieldFromName(field.toStdString());
    return !f || isStale(*f);
}

QGeoCoordinate Vehicle::position() const
{
    const double lat = value(TelemetryField::Latitude), lon = value(TelemetryField::Longitude);
    if (std::isnan(lat) || std::isnan(lon))
        return {};
    const double alt = value(TelemetryField::AltitudeAmsl);
    return std::isnan(alt) ? QGeoCoordinate(lat, lon) : QGeoCoordinate(lat, lon, alt);
}

QGeoCoordinate Vehicle::home() const
{
    const double lat = value(TelemetryField::HomeLatitude), lon = value(TelemetryField::HomeLongitude);
    if (std::isnan(lat) || std::isnan(lon))
        return {};
    const double alt = value(TelemetryField::HomeAltitudeAmsl);
    return std::isnan(alt) ? QGeoCoordinate(lat, lon) : QGeoCoordinate(lat, lon, alt);
}

QString Vehicle::mode() const
{
    const std::string_view n = modeName(flightMode());
    return QString::fromLatin1(n.data(), qsizetype(n.size()));
}

QString Vehicle::missionState() const
{
    const std::string_view n = missionStateName(MissionState(int(value(TelemetryField::MissionState, 0))));
    return QString::fromLatin1(n.data(), qsizetype(n.size()));
}

VehicleLink::Done Vehicle::finisher(const QString &command, const QString &logged)
{
    // Called as the command is sent: it goes into the command log now, its result when it comes.
    VehicleLink::Done log = m_commandLog ? m_commandLog->track(name(), logged.isEmpty() ? command : logged) : VehicleLink::Done();
    // Queued, so the result never arrives inside the call that asked for it.
    return [self = QPointer<Vehicle>(this), command, log](const CommandResult &r) {
        if (log)
            log(r);
        if (!self)
            return;
        QMetaObject::invokeMethod(self, [self, command, r] {
            if (self)
                emit self->commandFinished(command, r.ok, r.message);
        }, Qt::QueuedConnection);
    };
}

void Vehicle::readParameters()
{
    // Read once per connection: the vehicle's own limits and defaults (take-off altitude, battery
    // levels) that the command policy and the instruments prefer over the client's settings.
    m_link->readParameters([self = QPointer<Vehicle>(this)](const CommandResult &result, const QVariantMap &values) {
        if (!self || !result.ok || values == self->m_parameters)
            return;
        self->m_parameters = values;
        emit self->parametersChanged();
    });
}

void Vehicle::setCommandLog(CommandLog *log)
{
    m_commandLog = log;
}

void Vehicle::arm()
{
    if (m_link)
        m_link->arm(true, finisher(QStringLiteral("arm")));
}

void Vehicle::disarm()
{
    if (m_link)
        m_link->arm(false, finisher(QStringLiteral("disarm")));
}

void Vehicle::setMode(const QString &mode)
{
    const FlightMode m = modeFromName(mode.toStdString());
    const QString logged = QCoreApplication::translate("Vehicle", "mode %1").arg(mode);
    if (m == FlightMode::Unknown) {
        finisher(QStringLiteral("mode"), logged)(CommandResult::failure(QCoreApplication::translate("Vehicle", "\"%1\" is not a flight mode").arg(mode)));
        return;
    }
    if (m_link)
        m_link->setMode(m, finisher(QStringLiteral("mode"), logged));
}

void Vehicle::takeoff(double altitude)
{
    if (m_link)
        m_link->takeoff(altitude, finisher(QStringLiteral("takeoff"), QCoreApplication::translate("Vehicle", "takeoff to %1 m").arg(altitude)));
}

void Vehicle::land()
{
    if (m_link)
        m_link->land(finisher(QStringLiteral("land")));
}

void Vehicle::returnHome()
{
    if (m_link)
        m_link->returnHome(finisher(QStringLiteral("returnHome"), QCoreApplication::translate("Vehicle", "return home")));
}

} // namespace sortie::vehicle
