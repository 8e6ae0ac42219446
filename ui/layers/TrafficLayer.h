#pragma once

#include "MapLayer.h"

#include <QPointer>

#include <vector>

namespace sortie::traffic {
class Traffic;
}
Q_MOC_INCLUDE("Traffic.h")

namespace sortie::ui {

// Manned traffic on the map (core/traffic's picture): each aircraft a chevron along its track, a
// heading vector as long as the ground it covers in a minute, and a label with its call sign (its
// address when it sent none), its altitude (metres or feet; "std" when pressure altitude) and an
// arrow up or down while it climbs or descends faster than 0.5 m/s. Stale aircraft (not heard for a
// minute) are drawn faded. Labels never overlap (LabelPlacer), fresh ones placed first. While it is
// shown, the layer tells the traffic what the map shows, so the server is asked about that area.
class TrafficLayer : public MapLayer
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(sortie::traffic::Traffic *traffic READ traffic WRITE setTraffic NOTIFY trafficChanged)
    Q_PROPERTY(bool imperial READ imperial WRITE setImperial NOTIFY trafficChanged)
    Q_PROPERTY(int drawnCount READ drawnCount NOTIFY drawn) // aircraft with a position

public:
    static constexpr double kClimbThresholdMps = 0.5;
    static constexpr double kVectorSeconds = 60;

    explicit TrafficLayer(QQuickItem *parent = nullptr);

    traffic::Traffic *traffic() const { return m_traffic; }
    void setTraffic(traffic::Traffic *traffic);
    bool imperial() const { return m_imperial; }
    void setImperial(bool imperial);
    int drawnCount() const { return int(m_marks.size()); }

    // For tests and tooltips, by drawn index (0..drawnCount-1), in this item's coordinates.
    Q_INVOKABLE QPointF aircraftPosition(int index) const;
    Q_INVOKABLE QRectF labelRect(int index) const;
    Q_INVOKABLE QString labelText(int index) const; // the label's lines, joined by a space
    Q_INVOKABLE bool isStale(int index) const;

    void paint(QPainter *painter) override;

signals:
    void trafficChanged();
    void drawn();

protected:
    void onLanguageChanged() override
    {
        layOut();
        repaint();
    }
    void onViewportChanged() override;

private:
    struct Mark
    {
        QPointF at;          // in paintViewport pixels
        QPointF vectorEnd;   // = at without a track
        std::optional<double> trackDeg;
        QString callsign;
        QString altitude;    // "250 m", "820 ft std"; empty when unknown
        int trend = 0;       // +1 climbing, -1 descending, 0 level or unknown
        bool stale = false;
        QRectF label;
        bool labelMoved = false;
    };
    void layOut();
    void tellView();

    QPointer<traffic::Traffic> m_traffic;
    bool m_imperial = false;
    std::vector<Mark> m_marks;
};

} // namespace sortie::ui
