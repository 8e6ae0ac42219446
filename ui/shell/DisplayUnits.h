#pragma once

#include <QGeoCoordinate>
#include <QObject>
#include <QVariant>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// How numbers are shown to the operator: metric or imperial distances, speeds and altitudes in the
// language's number format (12,5 m in German), and decimal or degrees-minutes-seconds coordinates
// (always with a dot). Views format through it; nothing else
// converts units.
class DisplayUnits : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(System system READ system WRITE setSystem NOTIFY changed)
    Q_PROPERTY(CoordinateFormat coordinateFormat READ coordinateFormat WRITE setCoordinateFormat NOTIFY changed)
    Q_PROPERTY(QString systemName READ systemName WRITE setSystemName NOTIFY changed)
    Q_PROPERTY(bool imperial READ isImperial NOTIFY changed)
    // The UI's language (Translations::active): numbers follow its format (QLocale's default), so a
    // change re-formats every bound value.
    Q_PROPERTY(QString language READ language WRITE setLanguage NOTIFY changed)

public:
    enum class System { Metric, Imperial };
    Q_ENUM(System)
    enum class CoordinateFormat { Decimal, DegreesMinutesSeconds };
    Q_ENUM(CoordinateFormat)

    explicit DisplayUnits(QObject *parent = nullptr);

    System system() const { return m_system; }
    void setSystem(System system);
    CoordinateFormat coordinateFormat() const { return m_coordinates; }
    void setCoordinateFormat(CoordinateFormat format);
    // "metric" or "imperial", as settings store it.
    QString systemName() const;
    void setSystemName(const QString &name);
    bool isImperial() const { return m_system == System::Imperial; }
    QString language() const { return m_language; }
    void setLanguage(const QString &language);

    Q_INVOKABLE QString formatDistance(double meters) const;
    Q_INVOKABLE QString formatAltitude(double meters) const;
    Q_INVOKABLE QString formatSpeed(double metersPerSecond) const;
    Q_INVOKABLE QString formatCoordinate(const QGeoCoordinate &coordinate) const;
    Q_INVOKABLE QString formatLatLon(double latitude, double longitude) const;
    // "4:05" under an hour, "1:02:03" above; "—" when unknown.
    Q_INVOKABLE QString formatDuration(double seconds) const;
    // Degrees (as the Vehicle gives every angle) shown whole, "—" when unknown. A heading is folded
    // into 0..359.
    Q_INVOKABLE QString formatAngle(double degrees) const;
    Q_INVOKABLE QString formatHeading(double degrees) const;
    // What the vehicle reports of its battery: "87 %  22.4 V", "22.4 V" (voltage only),
    // "87 %" (level only), or "—" (nothing). `remaining` is 0..1.
    Q_INVOKABLE QString formatBattery(double voltage, double remaining) const;
    // The link's state (VehicleLink::State) in words: "connected", "link lost"...
    Q_INVOKABLE QString formatLinkState(int state) const;

    // A field's number as the operator reads and types it (core/i18n/TypedNumber): "40,5" in German;
    // `decimals` places, or the shortest exact text when negative.
    Q_INVOKABLE QString formatNumber(double value, int decimals = -1) const;
    // What the operator typed in a number field: the language's format or a dot decimal; undefined
    // (in QML) when it is no number, so the field can say so rather than take NaN.
    Q_INVOKABLE QVariant parseNumber(const QString &text) const;

signals:
    void changed();

private:
    System m_system = System::Metric;
    CoordinateFormat m_coordinates = CoordinateFormat::Decimal;
    QString m_language;
};

} // namespace sortie::ui
