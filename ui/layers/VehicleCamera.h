#pragma once

#include "VehicleMark.h"

#include <QObject>
#include <QPointer>

#include <vector>

namespace sortie::ui {

class MapView;

// Moves a map for the operator watching vehicles: fitAll() frames every vehicle, centerOn()
// one of them; `follow` keeps the current vehicle in the middle half of the map, and `autoFit`
// frames the fleet whenever a vehicle first reports where it is, until the operator moves the
// map (a pan or a zoom, not a resize). It reads the vehicles the layer keeps.
class VehicleCamera : public QObject
{
    Q_OBJECT

public:
    explicit VehicleCamera(const std::vector<VehicleMark> &vehicles, QObject *parent = nullptr);

    void setMap(MapView *map);
    bool follow() const { return m_follow; }
    void setFollow(bool follow);
    bool autoFit() const { return m_autoFit; }
    void setAutoFit(bool on);
    // The vehicle `follow` keeps in view (-1: none).
    void setCurrent(int row);

    // Frames every vehicle that has a position (and its home); false when none has one or the
    // map has no room yet.
    bool fitAll(qreal margin);
    // Moves the map so that the vehicle is in its middle; false when it has no position.
    bool centerOn(int row);
    // After new positions: frames the fleet (autoFit) or brings the current vehicle back (follow).
    void keepInView();

signals:
    void followChanged();
    void autoFitChanged();

private:
    struct Frame
    {
        double latitude = 0, longitude = 0, zoom = -1;
    };
    void onMapMoved();
    void remember();
    int positionedCount() const;

    const std::vector<VehicleMark> &m_vehicles;
    QPointer<MapView> m_map;
    int m_current = -1;
    bool m_follow = false;
    bool m_autoFit = false;
    bool m_movingMap = false; // the map moves because this camera moved it
    int m_fittedCount = 0;    // vehicles with a position when autoFit last framed them
    Frame m_framed;           // where this camera last put the map
};

} // namespace sortie::ui
