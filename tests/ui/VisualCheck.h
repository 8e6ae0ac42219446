#pragma once

#include <QQuickItem>
#include <QStringList>

namespace sortie::test {

// Looks at every Text shown under `scope` (a page, or a popup's item) and reports, one line each:
//  - clipped text: wider than its item (implicit or content width against width), unless it is
//    elided on purpose;
//  - text out of its frame: reaching past the popup it is in, or past the window;
//  - overlapping texts: two texts' painted boxes that cross (neither inside the other's item);
//  - missing glyphs: a character that neither the text's font nor any installed font has.
// Texts scrolled out of a clipping view are not judged.
QStringList inspectTexts(QQuickItem *scope);

// How many texts the last inspectTexts() judged (so a test knows it looked at something).
int lastInspectedTextCount();

// Looks at the controls laid on a map (the visible items under `pane`, the MapPane, named in
// `controls`) and reports, one line each, a control that covers one of the map's graticule labels
// as they are drawn now, or reaches into the bands where labels go (MapView::labelBandTop/Left),
// two controls that cover each other, and two labels that cross.
QStringList inspectMapControls(QQuickItem *pane, const QStringList &controls);

} // namespace sortie::test
