#pragma once

#include "FlownPath.h"
#include "Zone.h"

// Boost 1.74's validity and overlay checks rescale coordinates to 64-bit integers by default and can
// overflow them on far-apart rings (fuzz_kml_zones found a hole far outside its zone: signed overflow
// in determinant.hpp). Without the rescaling they work in doubles, as later Boost versions do by
// default. Defined before the first Boost.Geometry header of every file that uses it.
#ifndef BOOST_GEOMETRY_NO_ROBUSTNESS
#define BOOST_GEOMETRY_NO_ROBUSTNESS
#endif
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/geometries/segment.hpp>

#include <vector>

namespace sortie::airspace {

namespace bg = boost::geometry;
using PlaneXY = bg::model::d2::point_xy<double>;
using PlanePolygon = bg::model::polygon<PlaneXY>;  // clockwise, closed (bg::correct makes it so)
using PlaneMultiPolygon = bg::model::multi_polygon<PlanePolygon>;
using PlaneBox = bg::model::box<PlaneXY>;
using PlaneSegment = bg::model::segment<PlaneXY>;
using PlaneLine = bg::model::linestring<PlaneXY>;

// A parameter range [from, to] within one straight piece of a leg (0 at its first point, 1 at the
// next), and whether the heights there were unknown (so the piece was taken as inside).
struct Span
{
    double from = 0.0, to = 0.0;
    bool heightUnknown = false;
};

// A zone on a route's tangent plane: polygons as Boost.Geometry polygons; a circle or cone frustum
// as its centre and radii.
class PlaneZone
{
public:
    PlaneZone(const Zone &zone, int index, const LocalTangentPlane &plane);

    int index() const { return m_index; }
    const Zone &zone() const { return *m_zone; }
    const PlaneBox &envelope() const { return m_envelope; }  // horizontal, widest radius for a cone

    // Where the straight piece a -> b (heights linear between them) is inside the zone in 3D.
    std::vector<Span> inside(const FlownPoint &a, const FlownPoint &b) const;
    // How close the piece comes to the zone (exclusion: to its space; inclusion: to its edge,
    // horizontally or to its floor or ceiling); NaN when it cannot be said.
    double clearance(const FlownPoint &a, const FlownPoint &b) const;

private:
    // Horizontal: where the piece's shadow is over the polygons.
    std::vector<Span> overPolygons(const PlaneXY &a, const PlaneXY &b) const;
    // Where the heights are between floor and ceiling ([0, 1] flagged when unknown).
    std::vector<Span> betweenLimits(const FlownPoint &a, const FlownPoint &b) const;
    std::vector<Span> insideRound(const FlownPoint &a, const FlownPoint &b) const;

    const Zone *m_zone;
    int m_index;
    PlaneMultiPolygon m_polygons;
    PlaneXY m_center{0, 0};
    double m_bottomRadius = 0.0, m_topRadius = 0.0;
    bool m_round = false, m_cone = false;
    PlaneBox m_envelope;
};

// Sorted, overlapping or touching spans joined (unknown if any joined part was).
std::vector<Span> joinSpans(std::vector<Span> spans);
// a ∩ b, both sorted and disjoint.
std::vector<Span> intersectSpans(const std::vector<Span> &a, const std::vector<Span> &b);
// [0, 1] minus the spans.
std::vector<Span> complementSpans(const std::vector<Span> &spans);

} // namespace sortie::airspace
