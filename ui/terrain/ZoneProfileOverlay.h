#pragma once

#include "ElevationProfileView.h"

#include <QPointer>
#include <QQuickPaintedItem>
#include <QtQml/qqmlregistration.h>

namespace sortie::airspace {
class Airspace;
struct ZoneCrossing;
} // namespace sortie::airspace

namespace sortie::ui {

// Over the elevation profile: where the route crosses a zone (the store's crossings, from the
// airspace check: from/to metres along the flown path), the zone's floor and ceiling drawn at those
// distances in the profile's axes — AMSL as given, AGL over the profile's ground, above home over
// home's ground; no floor is the ground, no ceiling the top of the plot. Exclusion zones hatched
// red, inclusion zones (a fence left) green; the zone's name over the band, where it fits.
class ZoneProfileOverlay : public QQuickPaintedItem
{
    Q_OBJECT
    Q_MOC_INCLUDE("Airspace.h")
    QML_ELEMENT
    Q_PROPERTY(sortie::ui::ElevationProfileView *view READ view WRITE setView NOTIFY viewChanged)
    Q_PROPERTY(sortie::airspace::Airspace *airspace READ airspace WRITE setAirspace NOTIFY airspaceChanged)
    Q_PROPERTY(int bandCount READ bandCount NOTIFY painted)

public:
    explicit ZoneProfileOverlay(QQuickItem *parent = nullptr);

    ElevationProfileView *view() const { return m_view; }
    void setView(ElevationProfileView *view);
    airspace::Airspace *airspace() const;
    void setAirspace(airspace::Airspace *airspace);
    int bandCount() const { return m_bands; }
    // The band of crossing `index` as drawn (item coordinates, its bounding box); empty when not drawn.
    Q_INVOKABLE QRectF bandRect(int index) const;

    void paint(QPainter *painter) override;

signals:
    void viewChanged();
    void airspaceChanged();
    void painted();

private:
    QPolygonF bandOf(const airspace::ZoneCrossing &crossing) const;
    void followModel();

    QPointer<ElevationProfileView> m_view;
    QPointer<airspace::Airspace> m_airspace;
    int m_bands = 0;
    QMetaObject::Connection m_profile;
};

} // namespace sortie::ui
