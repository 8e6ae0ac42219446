#include "DisplayUnits.h"

#include <cmath>

namespace sortie::ui {

namespace {
constexpr double kFoot = 0.3048;
constexpr double kMile = 1609.344;

QString dms(double value, QChar positive, QChar negative)
{
    const QChar hemisphere = value < 0 ? negative : positive;
    double rest = std::abs(value);
    int degrees = int(rest);
    rest = (rest - degrees) * 60.0;
    int minutes = int(rest);
    double seconds = (rest - minutes) * 60.0;
    if (seconds >= 59.995) {
        seconds = 0;
        if (++minutes == 60) {
            minutes = 0;
            ++degrees;
        }
    }
    return QStringLiteral("%1°%2′%3″%4")
        .arg(degrees)
        .arg(minutes, 2, 10, QLatin1Char('0'))
        .arg(seconds, 5, 'f', 2, QLatin1Char('0'))
        .arg(hemisphere);
}
} // namespace

DisplayUnits::DisplayUnits(QObject *parent)
    : QObject(parent)
{
}

void DisplayUnits::setSystem(System system)
{
    if (system == m_system)
        return;
    m_system = system;
    emit changed();
}

void DisplayUnits::setCoordinateFormat(CoordinateFormat format)
{
    if (format == m_coordinates)
        return;
    m_coordinates = format;
    emit changed();
}

QString DisplayUnits::systemName() const
{
    return isImperial() ? QStringLiteral("imperial") : QStringLiteral("metric");
}

void DisplayUnits::setSystemName(const QString &name)
{
    setSystem(name.compare(QLatin1String("imperial"), Qt::CaseInsensitive) == 0 ? System::Imperial : System::Metric);
}

QString DisplayUnits::formatDistance(double meters) const
{
    if (!std::isfinite(meters))
        return QStringLiteral("—");
    if (isImperial()) {
        if (std::abs(meters) >= kMile)
            return tr("%1 mi").arg(meters / kMile, 0, 'f', 2);
        return tr("%1 ft").arg(std::round(meters / kFoot));
    }
    if (std::abs(meters) >= 1000)
        return tr("%1 km").arg(meters / 1000.0, 0, 'f', 2);
    return tr("%1 m").arg(meters, 0, 'f', std::abs(meters) < 10 ? 1 : 0);
}

QString DisplayUnits::formatAltitude(double meters) const
{
    if (!std::isfinite(meters))
        return QStringLiteral("—");
    if (isImperial())
        return tr("%1 ft").arg(std::round(meters / kFoot));
    return tr("%1 m").arg(meters, 0, 'f', 1);
}

QString DisplayUnits::formatSpeed(double metersPerSecond) const
{
    if (!std::isfinite(metersPerSecond))
        return QStringLiteral("—");
    if (isImperial())
        return tr("%1 mph").arg(metersPerSecond * 3600.0 / kMile, 0, 'f', 1);
    return tr("%1 m/s").arg(metersPerSecond, 0, 'f', 1);
}

QString DisplayUnits::formatCoordinate(const QGeoCoordinate &coordinate) const
{
    if (!coordinate.isValid())
        return QStringLiteral("—");
    return formatLatLon(coordinate.latitude(), coordinate.longitude());
}

QString DisplayUnits::formatLatLon(double latitude, double longitude) const
{
    if (m_coordinates == CoordinateFormat::DegreesMinutesSeconds)
        return dms(latitude, u'N', u'S') + QLatin1Char(' ') + dms(longitude, u'E', u'W');
    return QStringLiteral("%1, %2").arg(latitude, 0, 'f', 6).arg(longitude, 0, 'f', 6);
}

} // namespace sortie::ui
