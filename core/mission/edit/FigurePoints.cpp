// The editable points of a segment's figure: set, insert and erase one, whatever holds them.
#include "FigurePoints.h"

#include "AlgorithmSegment.h"
#include "AreaScan.h"

#include <algorithm>

namespace sortie::mission {

void FigurePoints::set(int i, const GeoPoint &p)
{
    if (corners) (*corners)[size_t(i)] = p;
    else (*points)[size_t(i)].position = p;
}

void FigurePoints::insert(int i, const GeoPoint &p)
{
    if (corners) {
        corners->insert(corners->begin() + i, p);
    } else {
        FigurePoint f = points->empty() ? FigurePoint{} : (*points)[size_t(std::max(0, i - 1))];
        f.position = p;
        points->insert(points->begin() + i, f);
    }
}

void FigurePoints::erase(int i)
{
    if (corners) corners->erase(corners->begin() + i);
    else points->erase(points->begin() + i);
}

FigurePoints figurePointsOf(Segment &s)
{
    if (AreaScan *a = asAreaScan(s))
        return {&a->polygon, nullptr, FigureType::Polygon};
    if (AlgorithmSegment *a = asAlgorithmSegment(s))
        return {nullptr, &a->points, a->figure};
    return {};
}

} // namespace sortie::mission
