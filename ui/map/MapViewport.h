#pragma once

#include <QGeoCoordinate>
#include <QPointF>
#include <QRectF>
#include <QSizeF>

namespace sortie::ui {

// What the map shows: a centre (normalised Web Mercator), a fractional zoom and a size in
// pixels. A value type with the conversions every map layer needs, so layers and tests can
// project without a scene.
class MapViewport
{
public:
    static constexpr double kMinZoom = 0.0;
    static constexpr double kMaxZoom = 22.0;

    MapViewport() = default;
    MapViewport(QPointF centre, double zoom, QSizeF size);

    QPointF centre() const { return m_centre; }
    double zoom() const { return m_zoom; }
    QSizeF size() const { return m_size; }
    // Pixels per normalised unit at this zoom.
    double scale() const { return m_scale; }

    void setCentre(QPointF normalised);
    void setZoom(double zoom);
    void setSize(QSizeF size) { m_size = size; }

    // Screen position of a normalised point, using the copy of the world nearest the centre.
    QPointF toScreen(QPointF normalised) const;
    // Screen position without choosing a world copy: for shapes already made continuous.
    QPointF toScreenUnwrapped(QPointF normalised) const;
    QPointF toNormalised(QPointF screen) const;
    QPointF geoToScreen(const QGeoCoordinate &coordinate) const;
    QGeoCoordinate screenToGeo(QPointF screen) const;
    // The normalised rectangle on screen (x may reach outside [0, 1] across the antimeridian).
    QRectF visibleNormalised() const;
    double metersPerPixel() const;

    void panByPixels(QPointF delta);
    // Changes the zoom while the point under `screen` stays where it is.
    void zoomAround(QPointF screen, double zoom);

    bool operator==(const MapViewport &other) const = default;

private:
    QPointF m_centre{0.5, 0.5};
    double m_zoom = 2.0;
    double m_scale = 1024.0;
    QSizeF m_size;
};

} // namespace sortie::ui
