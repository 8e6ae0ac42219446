#pragma once

#include <QAbstractItemModel>
#include <QColor>
#include <QPointer>
#include <QQuickPaintedItem>
#include <QVariant>
#include <QStringList>

#include <vector>

namespace sortie::vehicle {
class Vehicle;
}

namespace sortie::ui {

// A plot of telemetry over the last `windowSeconds`, from the vehicles' histories
// (TelemetryStore), which keep far more than a minute. Each series is one field of one vehicle,
// in its own colour; series with the same unit share a vertical range and an axis, so metres
// compare with metres; a second unit gets its axis on the right, any further ones their range
// in the legend. Two uses:
//  - one vehicle (`vehicle`), several `fields`;
//  - `compare`: the same `fields` for every vehicle of `fleet` (a list model with a "vehicle"
//    role), one colour per vehicle as on the map.
// Redraws when a plotted vehicle reports (at most at its notify rate).
class TelemetryPlot : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(QObject *vehicle READ vehicle WRITE setVehicle NOTIFY vehicleChanged)
    Q_PROPERTY(QAbstractItemModel *fleet READ fleet WRITE setFleet NOTIFY vehicleChanged)
    Q_PROPERTY(bool compare READ compare WRITE setCompare NOTIFY vehicleChanged)
    Q_PROPERTY(QStringList fields READ fields WRITE setFields NOTIFY fieldsChanged)
    Q_PROPERTY(double windowSeconds READ windowSeconds WRITE setWindowSeconds NOTIFY windowSecondsChanged)
    Q_PROPERTY(int sampleCount READ sampleCount NOTIFY plotted)
    Q_PROPERTY(int seriesCount READ seriesCount NOTIFY plotted)
    Q_PROPERTY(int axisCount READ axisCount NOTIFY plotted)
    // Every field a plot can show, named for the operator: [{key, name}] (a language change re-words it).
    Q_PROPERTY(QStringList fieldTitles READ fieldTitles NOTIFY fieldTitlesChanged)
    Q_PROPERTY(QColor textColor MEMBER m_textColor NOTIFY fieldsChanged)

public:
    explicit TelemetryPlot(QQuickItem *parent = nullptr);

    QObject *vehicle() const;
    void setVehicle(QObject *vehicle);
    QAbstractItemModel *fleet() const { return m_fleet; }
    void setFleet(QAbstractItemModel *fleet);
    bool compare() const { return m_compare; }
    void setCompare(bool compare);
    QStringList fields() const { return m_fields; }
    void setFields(const QStringList &fields);
    double windowSeconds() const { return m_windowSeconds; }
    void setWindowSeconds(double seconds);
    // What the last layout drew: samples over all series, series, and unit groups (axes).
    int sampleCount() const { return m_sampleCount; }
    int seriesCount() const { return int(m_series.size()); }
    int axisCount() const { return int(m_groups.size()); }
    // For tests: series i's label, colour and unit group.
    Q_INVOKABLE QString seriesLabel(int i) const;
    Q_INVOKABLE QColor seriesColor(int i) const;
    Q_INVOKABLE int seriesAxis(int i) const;
    // Every field a plot can show ("altitudeAgl", "groundSpeed", ...).
    Q_INVOKABLE static QStringList availableFields();
    // The same, as the operator reads them: [{key, name}], the name in the current language.
    // The fields' titles for the operator, in availableFields()' order (in the current language).
    static QStringList fieldTitles();

    void paint(QPainter *painter) override;

signals:
    void vehicleChanged();
    void fieldsChanged();
    void windowSecondsChanged();
    void plotted();
    void fieldTitlesChanged(); // the language changed

protected:
    void updatePolish() override;
    void itemChange(ItemChange change, const ItemChangeData &value) override;

private:
    struct Series
    {
        QString label;
        QColor colour;
        int group = 0;
        std::vector<QPointF> raw; // (ms since `from`, value in display units)
        QPolygonF points;         // in item pixels
        double last = 0;
    };
    struct Group
    {
        QString unit;
        QColor colour; // its first series'
        double minimum = 0;
        double maximum = 0;
    };
    QRectF plotArea() const;
    void redraw(); // lay out and draw again, while shown
    void watch();
    std::vector<std::pair<vehicle::Vehicle *, int>> sources() const; // vehicle and its colour row

    QPointer<vehicle::Vehicle> m_vehicle;
    QPointer<QAbstractItemModel> m_fleet;
    bool m_compare = false;
    std::vector<QPointer<vehicle::Vehicle>> m_watched;
    QStringList m_fields{QStringLiteral("altitudeAgl")};
    double m_windowSeconds = 300;
    double m_spanSeconds = 300;   // what the time axis shows: the window, or the history if shorter
    QColor m_textColor = Qt::black;
    std::vector<Series> m_series; // built in updatePolish
    std::vector<Group> m_groups;
    int m_sampleCount = 0;
};

} // namespace sortie::ui
