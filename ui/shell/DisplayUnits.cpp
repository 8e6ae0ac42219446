#include "DisplayUnits.h"

#include "TypedNumber.h"
#include "VehicleLink.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace sortie::ui {

namespace {
constexpr double kFoot = 0.3048;

// A number in the language's format (QLocale's default, which Translations sets): "12,5" in German.
// No thousands separators, as before: "1500 ft".
QString number(double value, int decimals)
{
    return i18n::formatTypedNumber(value, decimals);
}
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

void DisplayUnits::setLanguage(const QString &language)
{
    if (language == m_language)
        return;
    m_language = language;
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
            return tr("%1 mi").arg(number(meters / kMile, 2));
        return tr("%1 ft").arg(std::round(meters / kFoot));
    }
    if (std::abs(meters) >= 1000)
        return tr("%1 km").arg(number(meters / 1000.0, 2));
    return tr("%1 m").arg(number(meters, std::abs(meters) < 10 ? 1 : 0));
}

QString DisplayUnits::formatAltitude(double meters) const
{
    if (!std::isfinite(meters))
        return QStringLiteral("—");
    if (isImperial())
        return tr("%1 ft").arg(std::round(meters / kFoot));
    return tr("%1 m").arg(number(meters, 1));
}

QString DisplayUnits::formatSpeed(double metersPerSecond) const
{
    if (!std::isfinite(metersPerSecond))
        return QStringLiteral("—");
    if (isImperial())
        return tr("%1 mph").arg(number(metersPerSecond * 3600.0 / kMile, 1));
    return tr("%1 m/s").arg(number(metersPerSecond, 1));
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
    // Coordinates keep the dot in every language: "56.950000, 24.100000" is how they are typed and pasted.
    return QStringLiteral("%1, %2").arg(latitude, 0, 'f', 6).arg(longitude, 0, 'f', 6);
}

QString DisplayUnits::formatDuration(double seconds) const
{
    if (!std::isfinite(seconds) || seconds < 0)
        return QStringLiteral("—");
    const qint64 total = qint64(std::llround(seconds));
    const qint64 hours = total / 3600, minutes = (total / 60) % 60, rest = total % 60;
    if (hours > 0)
        return QStringLiteral("%1:%2:%3").arg(hours).arg(minutes, 2, 10, QLatin1Char('0')).arg(rest, 2, 10, QLatin1Char('0'));
    return QStringLiteral("%1:%2").arg(minutes).arg(rest, 2, 10, QLatin1Char('0'));
}

QString DisplayUnits::formatAngle(double degrees) const
{
    if (!std::isfinite(degrees))
        return QStringLiteral("—");
    const double whole = std::round(degrees);
    return QStringLiteral("%1°").arg(whole == 0 ? 0.0 : whole, 0, 'f', 0); // no "-0°"
}

QString DisplayUnits::formatHeading(double degrees) const
{
    if (!std::isfinite(degrees))
        return QStringLiteral("—");
    int whole = int(std::lround(degrees) % 360);
    if (whole < 0)
        whole += 360;
    return QStringLiteral("%1°").arg(whole, 3, 10, QLatin1Char('0'));
}

QString DisplayUnits::formatBattery(double voltage, double remaining) const
{
    const bool hasLevel = std::isfinite(remaining), hasVoltage = std::isfinite(voltage);
    const QString level = hasLevel ? tr("%1 %").arg(std::lround(std::clamp(remaining, 0.0, 1.0) * 100)) : QString();
    const QString volts = hasVoltage ? tr("%1 V").arg(number(voltage, 1)) : QString();
    if (hasLevel && hasVoltage)
        return level + QStringLiteral("  ") + volts;
    if (hasLevel)
        return level;
    if (hasVoltage)
        return volts;
    return QStringLiteral("—");
}

QString DisplayUnits::formatLinkState(int state) const
{
    using State = vehicle::VehicleLink::State;
    switch (State(state)) {
    case State::Disconnected: return tr("disconnected");
    case State::Connecting: return tr("connecting");
    case State::Connected: return tr("connected");
    case State::Lost: return tr("link lost");
    }
    return QStringLiteral("—");
}

QString DisplayUnits::formatNumber(double value, int decimals) const
{
    return i18n::formatTypedNumber(value, decimals);
}

QVariant DisplayUnits::parseNumber(const QString &text) const
{
    const std::optional<double> value = i18n::parseTypedNumber(text);
    return value ? QVariant(*value) : QVariant();
}

} // namespace sortie::ui
