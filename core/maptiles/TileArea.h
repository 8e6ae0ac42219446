#pragma once

#include <QList>
#include <QPointF>
#include <QString>

namespace sortie::maptiles {

// A latitude/longitude box in degrees. West > east crosses the antimeridian.
struct GeoBounds
{
    double south = 0;
    double west = 0;
    double north = 0;
    double east = 0;

    bool isValid() const;
    // The box grown by `metres` on every side (latitudes kept within the Web Mercator limit).
    GeoBounds grown(double metres) const;
};

// The tiles of one row that an area covers at one zoom: columns first..last (inclusive).
struct TileSpan
{
    int row = 0;
    int firstColumn = 0;
    int lastColumn = 0;
    qint64 count() const { return qint64(lastColumn) - firstColumn + 1; }
};

// An area to take offline: a rectangle or a polygon (longitude/latitude corners). It answers which
// tiles cover it at each zoom, exactly: a tile counts when the area overlaps it with some surface.
class TileArea
{
public:
    TileArea() = default;
    static TileArea rectangle(const GeoBounds &bounds);
    // Corners as QPointF(longitude, latitude); at least three, not crossing the antimeridian.
    static TileArea polygon(const QList<QPointF> &lonLat);

    bool isEmpty() const { return m_corners.size() < 3; }
    bool isRectangle() const { return m_isRectangle; }
    // The corners as QPointF(longitude, latitude): a polygon's as given, a rectangle's four from
    // north-west clockwise. Empty when the area is.
    QList<QPointF> corners() const;
    // Why the area cannot be used, or empty.
    QString problem() const { return m_problem; }
    GeoBounds bounds() const { return m_bounds; }

    // Rows from north to south, each with the spans of columns covered (a concave polygon may
    // cover a row in several spans; an area across the antimeridian covers both ends).
    QList<TileSpan> spans(int zoom) const;
    qint64 tileCount(int zoom) const;
    qint64 tileCount(int minZoom, int maxZoom) const;

    static constexpr int kMaximumZoom = 24;
    static constexpr double kMaximumLatitude = 85.0511287798066;

private:
    QList<QPointF> m_lonLat;  // as given (a polygon's), for showing and keeping the area
    QList<QPointF> m_corners; // normalised Web Mercator (u eastwards, may pass 1 across the antimeridian; v southwards)
    GeoBounds m_bounds;
    QString m_problem;
    bool m_isRectangle = false;
};

} // namespace sortie::maptiles
