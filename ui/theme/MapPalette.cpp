#include "MapPalette.h"

namespace sortie::ui {

namespace {
// The marks' colours, the same in every scheme: their meaning does not change with the light.
MapPalette withMarks(MapPalette p)
{
    p.halo = QColor(255, 255, 255, 220);
    p.outline = QColor(0xff, 0xff, 0xff);
    p.markText = QColor(0xff, 0xff, 0xff);
    p.labelBox = QColor(255, 255, 255, 215);
    p.stale = QColor(0x90, 0x90, 0x90);
    p.attention = QColor(0xff, 0xd6, 0x00);
    p.selection = QColor(0x1e, 0x88, 0xe5, 150);
    p.inactive = QColor(0x61, 0x61, 0x61);
    p.inactiveEdge = QColor(0x75, 0x75, 0x75);
    p.route = QColor(0x1e, 0x88, 0xe5);
    p.draft = QColor(0xef, 0x6c, 0x00);
    p.ghost = QColor(0x8d, 0x8d, 0x8d);
    p.exclusion = QColor(0xd3, 0x2f, 0x2f);
    p.authorisation = QColor(0xef, 0x6c, 0x00);
    p.conditional = QColor(0xc7, 0x9a, 0x00);
    p.information = QColor(0x39, 0x49, 0xab);
    p.inclusion = QColor(0x2e, 0x7d, 0x32);
    p.crossing = QColor(0xe5, 0x39, 0x35);
    p.conflict = QColor(0xd5, 0x00, 0x00);
    p.traffic = QColor(0x00, 0x83, 0x8f);
    p.planned = QColor(0x43, 0xa0, 0x47);
    p.unplanned = QColor(0xfb, 0x8c, 0x00);
    p.noReturn = QColor(0xe5, 0x39, 0x35);
    p.terrain = QColor(0x9e, 0x9e, 0x9e);
    p.sky = QColor(0x3f, 0x8f, 0xd8);
    p.ground = QColor(0x8a, 0x5a, 0x2b);
    p.dial = QColor(0xff, 0xff, 0xff);
    p.sceneAmbient = QColor(0x80, 0x80, 0x80);
    return p;
}
} // namespace

MapPalette MapPalette::light()
{
    MapPalette p;
    p.sea = QColor(0xa9, 0xcf, 0xe3);
    p.sceneSky = QColor(0xc9, 0xdc, 0xee);
    p.land = QColor(0xef, 0xeb, 0xe0);
    p.coast = QColor(0x7c, 0x94, 0xa6);
    p.graticule = QColor(40, 60, 90, 70);
    p.label = QColor(0x33, 0x44, 0x55);
    return withMarks(p);
}

MapPalette MapPalette::dark()
{
    MapPalette p;
    p.sea = QColor(0x16, 0x26, 0x36);
    p.sceneSky = QColor(0x1d, 0x27, 0x33);
    p.land = QColor(0x3a, 0x40, 0x45);
    p.coast = QColor(0x6a, 0x7d, 0x8c);
    p.graticule = QColor(200, 220, 240, 60);
    p.label = QColor(0xc8, 0xd2, 0xdc);
    return withMarks(p);
}

MapPalette MapPalette::sunlight()
{
    MapPalette p;
    p.sea = QColor(0x00, 0x00, 0x00);
    p.sceneSky = QColor(0x00, 0x00, 0x00);
    p.land = QColor(0x4a, 0x4a, 0x4a);
    p.coast = QColor(0xff, 0xff, 0xff);
    p.graticule = QColor(255, 255, 255, 120);
    p.label = QColor(0xff, 0xff, 0xff);
    p = withMarks(p);
    // Brighter marks and a stronger halo, so a mark stands out on a screen washed by the sun.
    p.halo = QColor(255, 255, 255, 255);
    p.labelBox = QColor(255, 255, 255, 240);
    p.exclusion = QColor(0xff, 0x17, 0x44);
    p.authorisation = QColor(0xff, 0x91, 0x00);
    p.conditional = QColor(0xff, 0xea, 0x00);
    p.information = QColor(0x53, 0x6d, 0xfe);
    p.inclusion = QColor(0x00, 0xe6, 0x76);
    p.crossing = QColor(0xff, 0x17, 0x44);
    p.conflict = QColor(0xff, 0x17, 0x44);
    p.traffic = QColor(0x00, 0xe5, 0xff);
    return p;
}

} // namespace sortie::ui
