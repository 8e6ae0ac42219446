#pragma once

#include <QByteArray>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <optional>
#include <vector>

namespace sortie::ui {

// The world's land outlines (Natural Earth, public domain) in normalised Web Mercator, read
// from the compact file scripts/make-landmask.py writes (resources/land-50m.bin). Rings are
// continuous across the antimeridian, so a ring may reach outside x in [0, 1]; whoever draws
// them also draws the copies shifted by one world.
class LandOutlines
{
public:
    struct Polygon
    {
        QRectF bounds;                           // normalised, of the outer ring
        std::vector<std::vector<QPointF>> rings; // outer ring first, then holes
    };

    static constexpr auto kResourcePath = ":/sortie/basemap/land-50m.bin";

    // Parses the file's bytes; on failure returns nothing and says why in `error`.
    static std::optional<LandOutlines> fromData(const QByteArray &compressed, QString *error);
    static std::optional<LandOutlines> fromResource(QString *error);

    const std::vector<Polygon> &polygons() const { return m_polygons; }
    size_t pointCount() const { return m_points; }

private:
    std::vector<Polygon> m_polygons;
    size_t m_points = 0;
};

} // namespace sortie::ui
