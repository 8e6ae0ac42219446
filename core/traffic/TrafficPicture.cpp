#include "TrafficPicture.h"

#include "TrafficLog.h"

#include <QDateTime>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sortie::traffic {
namespace {

template<class T>
void take(std::optional<T> &held, const std::optional<T> &reported)
{
    if (reported)
        held = reported;
}

template<class T>
QVariant variant(const std::optional<T> &v)
{
    return v ? QVariant::fromValue(*v) : QVariant();
}

} // namespace

std::optional<TrafficVelocity> velocityOf(const TrafficReport &s)
{
    if (!s.groundSpeedMps || !s.trackDeg)
        return std::nullopt;
    const double track = *s.trackDeg * std::numbers::pi / 180.0;
    return TrafficVelocity{*s.groundSpeedMps * std::sin(track), *s.groundSpeedMps * std::cos(track), s.verticalRateMps};
}

TrafficPicture::TrafficPicture(Clock clock, QObject *parent)
    : QAbstractListModel(parent)
    , m_clock(clock ? std::move(clock) : Clock([] { return QDateTime::currentMSecsSinceEpoch(); }))
{
    m_sweep.setInterval(1000);
    connect(&m_sweep, &QTimer::timeout, this, &TrafficPicture::sweep);
    m_sweep.start();
    m_notify.setSingleShot(true);
    m_notify.setInterval(kNotifyMs);
    connect(&m_notify, &QTimer::timeout, this, &TrafficPicture::flush);
}

int TrafficPicture::rowOf(quint32 address, bool nonIcao) const
{
    return m_rows.value(keyOf(address, nonIcao), -1);
}

const TrafficAircraft *TrafficPicture::find(quint32 address, bool nonIcao) const
{
    const int row = rowOf(address, nonIcao);
    return row < 0 ? nullptr : &m_aircraft[size_t(row)];
}

double TrafficPicture::rangeOf(const TrafficReport &s) const
{
    if (!m_reference || !s.latitude || !s.longitude)
        return std::numeric_limits<double>::infinity();
    // Great-circle distance on a sphere of the Earth's mean radius: enough to rank aircraft by.
    constexpr double kEarthRadiusM = 6371008.8, kRad = std::numbers::pi / 180.0;
    const double lat = *s.latitude * kRad, lon = *s.longitude * kRad;
    const auto [refLat, refLon] = *m_reference;
    const double a = std::pow(std::sin((lat - refLat) / 2), 2) + std::cos(lat) * std::cos(refLat) * std::pow(std::sin((lon - refLon) / 2), 2);
    return 2 * kEarthRadiusM * std::asin(std::min(1.0, std::sqrt(a)));
}

int TrafficPicture::farthestRow()
{
    if (m_farthest >= 0 || m_aircraft.empty())
        return m_farthest;
    m_farthest = 0;
    for (size_t i = 1; i < m_aircraft.size() && !std::isinf(m_aircraft[size_t(m_farthest)].rangeM); ++i) {
        if (m_aircraft[i].rangeM > m_aircraft[size_t(m_farthest)].rangeM)
            m_farthest = int(i);
    }
    return m_farthest;
}

void TrafficPicture::touch(int row)
{
    m_dirtyFirst = m_dirtyFirst < 0 ? row : std::min(m_dirtyFirst, row);
    m_dirtyLast = std::max(m_dirtyLast, row);
    m_changed = true;
    if (!m_notify.isActive())
        m_notify.start();
}

void TrafficPicture::flush()
{
    m_notify.stop();
    if (m_dirtyFirst >= 0 && m_dirtyLast < count())
        emit dataChanged(createIndex(m_dirtyFirst, 0), createIndex(m_dirtyLast, 0));
    m_dirtyFirst = m_dirtyLast = -1;
    if (m_notifiedCount != count()) {
        m_notifiedCount = count();
        emit countChanged();
    }
    if (m_changed) {
        m_changed = false;
        emit changed();
    }
}

void TrafficPicture::reindex()
{
    m_rows.clear();
    m_rows.reserve(qsizetype(m_aircraft.size()));
    for (size_t i = 0; i < m_aircraft.size(); ++i)
        m_rows.insert(keyOf(m_aircraft[i].state.address, m_aircraft[i].state.nonIcaoAddress), int(i));
    m_farthest = -1;
}

void TrafficPicture::report(const TrafficReport &r)
{
    const qint64 now = m_clock();
    int row = rowOf(r.address, r.nonIcaoAddress);
    if (row < 0) {
        TrafficAircraft a;
        a.state.address = r.address;
        a.state.nonIcaoAddress = r.nonIcaoAddress;
        a.firstSeenMs = now;
        a.lastSeenMs = now;
        if (r.latitude && r.longitude)
            a.rangeM = rangeOf(r);
        if (count() < m_capacity) {
            row = count();
            beginInsertRows({}, row, row);
            m_aircraft.push_back(a);
            m_rows.insert(keyOf(r.address, r.nonIcaoAddress), row);
            endInsertRows();
            if (m_farthest >= 0 && !(a.rangeM <= m_aircraft[size_t(m_farthest)].rangeM))
                m_farthest = row;
        } else {
            // Full: the newcomer takes the farthest one's row if it is nearer, else it is left out.
            row = farthestRow();
            TrafficAircraft &far = m_aircraft[size_t(row)];
            if (!(a.rangeM < far.rangeM)) {
                ++m_leftOut;
                return;
            }
            qCDebug(lcTraffic).noquote() << "aircraft" << addressText(r) << "replaces the farthest," << addressText(far.state);
            m_rows.remove(keyOf(far.state.address, far.state.nonIcaoAddress));
            far = a;
            m_rows.insert(keyOf(r.address, r.nonIcaoAddress), row);
            m_farthest = -1;
        }
        qCDebug(lcTraffic).noquote() << "aircraft" << addressText(r) << "from" << sourceName(r.source);
    }
    TrafficAircraft &a = m_aircraft[size_t(row)];
    TrafficReport &s = a.state;
    const bool repeated = r.sourceTimeMs && s.sourceTimeMs && *r.sourceTimeMs == *s.sourceTimeMs && s.source == r.source;
    s.source = r.source;
    take(s.callsign, r.callsign);
    if (r.latitude && r.longitude) {
        s.latitude = r.latitude;
        s.longitude = r.longitude;
        const double before = a.rangeM;
        a.rangeM = rangeOf(s);
        if (m_farthest >= 0) {
            if (row == m_farthest ? a.rangeM < before : a.rangeM > m_aircraft[size_t(m_farthest)].rangeM)
                m_farthest = row == m_farthest ? -1 : row;
        }
    }
    const bool msl = r.altitudeReference == AltitudeReference::MeanSeaLevel;
    if (r.altitudeM && (msl || a.mslAltitudeMs == 0 || now - a.mslAltitudeMs >= kMslAltitudePreferredMs)) {
        s.altitudeM = r.altitudeM;
        s.altitudeReference = r.altitudeReference;
        if (msl)
            a.mslAltitudeMs = now;
    }
    take(s.groundSpeedMps, r.groundSpeedMps);
    take(s.trackDeg, r.trackDeg);
    take(s.verticalRateMps, r.verticalRateMps);
    take(s.squawk, r.squawk);
    take(s.onGround, r.onGround);
    take(s.sourceTimeMs, r.sourceTimeMs);
    if (!repeated) {
        a.lastSeenMs = now;
        a.stale = false;
    }
    touch(row);
}

void TrafficPicture::setCapacity(int capacity)
{
    capacity = std::max(1, capacity);
    if (capacity == m_capacity)
        return;
    m_capacity = capacity;
    if (count() <= m_capacity)
        return;
    flush();
    while (count() > m_capacity) {
        const int row = farthestRow();
        beginRemoveRows({}, row, row);
        m_aircraft.erase(m_aircraft.begin() + row);
        endRemoveRows();
        m_farthest = -1;
    }
    reindex();
    m_notifiedCount = count();
    emit countChanged();
    emit changed();
}

void TrafficPicture::setReference(double latitude, double longitude)
{
    constexpr double kRad = std::numbers::pi / 180.0;
    if (!std::isfinite(latitude) || !std::isfinite(longitude))
        return;
    m_reference = std::pair{latitude * kRad, longitude * kRad};
    for (TrafficAircraft &a : m_aircraft)
        a.rangeM = rangeOf(a.state);
    m_farthest = -1;
}

void TrafficPicture::sweep()
{
    flush();
    const qint64 now = m_clock();
    bool any = false, removed = false;
    for (int row = count() - 1; row >= 0; --row) {
        TrafficAircraft &a = m_aircraft[size_t(row)];
        const qint64 silent = now - a.lastSeenMs;
        if (silent >= kRemoveAfterMs) {
            qCDebug(lcTraffic).noquote() << "aircraft" << addressText(a.state) << "gone after" << silent / 1000 << "s";
            beginRemoveRows({}, row, row);
            m_aircraft.erase(m_aircraft.begin() + row);
            endRemoveRows();
            any = removed = true;
        } else if (silent >= kStaleAfterMs && !a.stale) {
            a.stale = true;
            const QModelIndex index = createIndex(row, 0);
            emit dataChanged(index, index, {StaleRole});
            any = true;
        }
    }
    if (removed) {
        reindex();
        m_notifiedCount = count();
        emit countChanged();
    }
    if (any)
        emit changed();
}

void TrafficPicture::clear()
{
    flush();
    if (m_aircraft.empty())
        return;
    beginResetModel();
    m_aircraft.clear();
    m_rows.clear();
    m_farthest = -1;
    endResetModel();
    m_notifiedCount = 0;
    emit countChanged();
    emit changed();
}

QString TrafficPicture::addressText(const TrafficReport &s)
{
    return (s.nonIcaoAddress ? QStringLiteral("~") : QString()) + QStringLiteral("%1").arg(s.address, 6, 16, QLatin1Char('0')).toUpper();
}

QString TrafficPicture::referenceName(AltitudeReference reference)
{
    return reference == AltitudeReference::Barometric ? QStringLiteral("barometric") : QStringLiteral("msl");
}

QString TrafficPicture::sourceName(TrafficSource source)
{
    return source == TrafficSource::Receiver ? QStringLiteral("receiver") : QStringLiteral("server");
}

int TrafficPicture::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

QVariant TrafficPicture::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    const TrafficAircraft &a = m_aircraft[size_t(index.row())];
    const TrafficReport &s = a.state;
    const auto velocity = velocityOf(s);
    switch (role) {
    case Qt::DisplayRole: return s.callsign.value_or(addressText(s));
    case AddressRole: return addressText(s);
    case CallsignRole: return variant(s.callsign);
    case LatitudeRole: return variant(s.latitude);
    case LongitudeRole: return variant(s.longitude);
    case AltitudeRole: return variant(s.altitudeM);
    case AltitudeReferenceRole: return s.altitudeM ? QVariant(referenceName(s.altitudeReference)) : QVariant();
    case GroundSpeedRole: return variant(s.groundSpeedMps);
    case TrackRole: return variant(s.trackDeg);
    case VerticalRateRole: return variant(s.verticalRateMps);
    case VelocityEastRole: return velocity ? QVariant(velocity->east) : QVariant();
    case VelocityNorthRole: return velocity ? QVariant(velocity->north) : QVariant();
    case VelocityUpRole: return velocity ? variant(velocity->up) : QVariant();
    case SquawkRole: return variant(s.squawk);
    case OnGroundRole: return variant(s.onGround);
    case LastSeenRole: return a.lastSeenMs;
    case StaleRole: return a.stale;
    case SourceRole: return sourceName(s.source);
    default: return {};
    }
}

QHash<int, QByteArray> TrafficPicture::roleNames() const
{
    return {{AddressRole, "address"}, {CallsignRole, "callsign"}, {LatitudeRole, "latitude"}, {LongitudeRole, "longitude"},
            {AltitudeRole, "altitude"}, {AltitudeReferenceRole, "altitudeReference"}, {GroundSpeedRole, "groundSpeed"},
            {TrackRole, "track"}, {VerticalRateRole, "verticalRate"}, {VelocityEastRole, "velocityEast"},
            {VelocityNorthRole, "velocityNorth"}, {VelocityUpRole, "velocityUp"}, {SquawkRole, "squawk"},
            {OnGroundRole, "onGround"}, {LastSeenRole, "lastSeen"}, {StaleRole, "stale"}, {SourceRole, "source"}};
}

} // namespace sortie::traffic
