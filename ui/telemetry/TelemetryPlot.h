#pragma once

#include <QColor>
#include <QPointer>
#include <QQuickPaintedItem>
#include <QStringList>

namespace sortie::vehicle {
class Vehicle;
}

namespace sortie::ui {

// A plot of telemetry fields of one vehicle over the last `windowSeconds`, from the vehicle's
// history (TelemetryStore), which keeps far more than a minute. Several fields share the time
// axis, each scaled to its own range and labelled with its latest value. Redraws when the vehicle
// reports (at most at its notify rate).
class TelemetryPlot : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QObject *vehicle READ vehicle WRITE setVehicle NOTIFY vehicleChanged)
    Q_PROPERTY(QStringList fields READ fields WRITE setFields NOTIFY fieldsChanged)
    Q_PROPERTY(double windowSeconds READ windowSeconds WRITE setWindowSeconds NOTIFY windowSecondsChanged)
    Q_PROPERTY(int sampleCount READ sampleCount NOTIFY plotted)
    Q_PROPERTY(QColor textColor MEMBER m_textColor NOTIFY fieldsChanged)

public:
    explicit TelemetryPlot(QQuickItem *parent = nullptr);

    QObject *vehicle() const;
    void setVehicle(QObject *vehicle);
    QStringList fields() const { return m_fields; }
    void setFields(const QStringList &fields);
    double windowSeconds() const { return m_windowSeconds; }
    void setWindowSeconds(double seconds);
    // Samples drawn in the last paint, over all fields.
    int sampleCount() const { return m_sampleCount; }
    // Every field a plot can show ("altitudeAgl", "groundSpeed", ...).
    Q_INVOKABLE static QStringList availableFields();

    void paint(QPainter *painter) override;

signals:
    void vehicleChanged();
    void fieldsChanged();
    void windowSecondsChanged();
    void plotted();

protected:
    void updatePolish() override;

private:
    struct Series
    {
        QString name;
        QString unit;
        QPolygonF points; // in item pixels
        double minimum = 0;
        double maximum = 0;
        double last = 0;
    };

    QPointer<vehicle::Vehicle> m_vehicle;
    QStringList m_fields{QStringLiteral("altitudeAgl")};
    double m_windowSeconds = 300;
    double m_spanSeconds = 300;   // what the time axis shows: the window, or the history if shorter
    QColor m_textColor = Qt::black;
    std::vector<Series> m_series; // built in updatePolish
    int m_sampleCount = 0;
};

} // namespace sortie::ui
