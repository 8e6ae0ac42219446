#pragma once

#include "ElevationProfileView.h"

#include <QPointer>
#include <QQuickPaintedItem>
#include <QVariant>
#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// Over the elevation profile: where the route crosses a zone (Airspace.crossings, from the
// airspace check: from/to metres along the flown path), the zone's floor and ceiling drawn at those
// distances in the profile's axes — AMSL as given, AGL over the profile's ground, above home over
// home's ground; no floor is the ground, no ceiling the top of the plot. Exclusion zones hatched
// red, inclusion zones (a fence left) green; the zone's name over the band, where it fits.
class ZoneProfileOverlay : public QQuickPaintedItem
{
    Q_OBJECT
    QML_ELEMENT
    Q_PROPERTY(sortie::ui::ElevationProfileView *view READ view WRITE setView NOTIFY viewChanged)
    Q_PROPERTY(QVariantList crossings READ crossings WRITE setCrossings NOTIFY crossingsChanged)
    Q_PROPERTY(int bandCount READ bandCount NOTIFY painted)

public:
    explicit ZoneProfileOverlay(QQuickItem *parent = nullptr);

    ElevationProfileView *view() const { return m_view; }
    void setView(ElevationProfileView *view);
    QVariantList crossings() const { return m_crossings; }
    void setCrossings(const QVariantList &crossings);
    int bandCount() const { return m_bands; }
    // The band of crossing `index` as drawn (item coordinates, its bounding box); empty when not drawn.
    Q_INVOKABLE QRectF bandRect(int index) const;

    void paint(QPainter *painter) override;

signals:
    void viewChanged();
    void crossingsChanged();
    void painted();

private:
    QPolygonF bandOf(const QVariantMap &crossing) const;
    void followModel();

    QPointer<ElevationProfileView> m_view;
    QVariantList m_crossings;
    int m_bands = 0;
    QMetaObject::Connection m_profile;
};

} // namespace sortie::ui
