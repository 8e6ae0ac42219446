#include "TrafficPicture.h"

#include "TrafficLog.h"

#include <QDateTime>

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
}

int TrafficPicture::rowOf(quint32 address, bool nonIcao) const
{
    for (size_t i = 0; i < m_aircraft.size(); ++i) {
        if (m_aircraft[i].state.address == address && m_aircraft[i].state.nonIcaoAddress == nonIcao)
            return int(i);
    }
    return -1;
}

const TrafficAircraft *TrafficPicture::find(quint32 address, bool nonIcao) const
{
    const int row = rowOf(address, nonIcao);
    return row < 0 ? nullptr : &m_aircraft[size_t(row)];
}

void TrafficPicture::report(const TrafficReport &r)
{
    const qint64 now = m_clock();
    int row = rowOf(r.address, r.nonIcaoAddress);
    if (row < 0) {
        row = count();
        beginInsertRows({}, row, row);
        TrafficAircraft a;
        a.state.address = r.address;
        a.state.nonIcaoAddress = r.nonIcaoAddress;
        a.firstSeenMs = now;
        a.lastSeenMs = now;
        m_aircraft.push_back(a);
        endInsertRows();
        emit countChanged();
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
    const QModelIndex index = createIndex(row, 0);
    emit dataChanged(index, index);
    emit changed();
}

void TrafficPicture::sweep()
{
    const qint64 now = m_clock();
    bool any = false;
    for (int row = count() - 1; row >= 0; --row) {
        TrafficAircraft &a = m_aircraft[size_t(row)];
        const qint64 silent = now - a.lastSeenMs;
        if (silent >= kRemoveAfterMs) {
            qCDebug(lcTraffic).noquote() << "aircraft" << addressText(a.state) << "gone after" << silent / 1000 << "s";
            beginRemoveRows({}, row, row);
            m_aircraft.erase(m_aircraft.begin() + row);
            endRemoveRows();
            emit countChanged();
            any = true;
        } else if (silent >= kStaleAfterMs && !a.stale) {
            a.stale = true;
            const QModelIndex index = createIndex(row, 0);
            emit dataChanged(index, index, {StaleRole});
            any = true;
        }
    }
    if (any)
        emit changed();
}

void TrafficPicture::clear()
{
    if (m_aircraft.empty())
        return;
    beginResetModel();
    m_aircraft.clear();
    endResetModel();
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
