#pragma once

#include <QString>

namespace sortie::app {

// Which scene graph draws the window. Where OpenGL is itself drawn by the CPU (Mesa's llvmpipe,
// softpipe or swrast: a virtual display such as Xvfb, a remote desktop, a machine without a GPU
// driver), every frame composites the whole window in the software rasteriser; Qt Quick's software
// scene graph repaints only the parts that changed, for a fraction of the CPU (docs/performance.md,
// "An idle client"). Without a GPU device that is certain; with one, OpenGL is asked for its
// renderer. Call after the QGuiApplication exists and before the first window; an explicit
// QT_QUICK_BACKEND or QSG_RHI_BACKEND is left alone. The choice goes to the log (sortie.scenegraph).
void chooseSceneGraph();

} // namespace sortie::app
