#pragma once

#include <QColor>

namespace sortie::ui {

// The colours of everything painted in C++ (the base map, the graticule, the layers' marks, the
// instruments, the plots), one value per scheme: Theme hands it out (Theme::mapPalette) and the
// map hands it to its layers (MapView::colours). The base map and the words on it follow the
// scheme; the marks keep their meaning in every scheme (a no-fly zone is red), drawn over a halo
// that keeps them apart from the map below.
struct MapPalette
{
    // The base map and the grid.
    QColor sea;
    QColor sceneSky;      // behind the 3D view's ground
    QColor sceneAmbient;  // the 3D view's ambient light (the sun's shade)
    QColor land;
    QColor coast;
    QColor graticule;
    QColor label;

    // Marks: outlines and the words in them.
    QColor halo;          // the light outline under words and legs on the map (translucent)
    QColor outline;       // the edge of a filled mark (a vehicle, a waypoint, a battery)
    QColor markText;      // words and numbers on a filled mark
    QColor labelBox;      // the box behind a label on the map
    QColor stale;         // a vehicle whose position is old
    QColor attention;     // the chosen vehicle's ring, the selected waypoint, the compass' heading
    QColor selection;     // a selected zone's glow
    QColor inactive;      // a zone switched off
    QColor inactiveEdge;

    // What the marks mean.
    QColor route;         // the open route's legs; an offline maps area
    QColor draft;         // a figure being drawn (an area scan's corners)
    QColor ghost;         // the server's copy of a route in conflict
    QColor exclusion;     // no-fly zones; a geographical zone that prohibits the flight
    QColor authorisation; // a geographical zone that needs an authorisation (REQ_AUTHORISATION)
    QColor conditional;   // a geographical zone with conditions (CONDITIONAL)
    QColor information;   // a geographical zone that only informs (NO_RESTRICTION)
    QColor inclusion;     // geofences (fly only inside)
    QColor crossing;      // a leg inside a zone
    QColor conflict;      // where routes meet
    QColor traffic;       // manned aircraft
    QColor planned;       // a planned battery change; on time; home
    QColor unplanned;     // an unplanned battery change; a little off; the next waypoint
    QColor noReturn;      // the point of no return; far off; north
    QColor terrain;       // the ground under the profile

    // Instruments.
    QColor sky;
    QColor ground;
    QColor dial;          // the fixed marks on a dial

    static MapPalette light();
    static MapPalette dark();
    // High contrast for sunlight: a black sea, grey land, white coast and words.
    static MapPalette sunlight();
    bool operator==(const MapPalette &) const = default;
};

} // namespace sortie::ui
