#pragma once

// The 3D view's test scene: an SRTM tile with a ridge, a route, zones, the real Scene3DView on an X
// display with OpenGL (Mesa's llvmpipe under Xvfb). Shared by tst_view3d and bench_view3d.
#include "Airspace.h"
#include "ElevationService.h"
#include "FlightScene.h"
#include "HgtTileSource.h"
#include "HgtWriter.h"
#include "QuickScene.h"
#include "RouteDocument.h"
#include "Theme.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QQuickWindow>
#include <QSettings>
#include <QTemporaryDir>

#include <cmath>
#include <memory>

namespace sortie::test {

// Before QGuiApplication: the X display (never offscreen, which test.sh exports) and OpenGL.
inline void useXWithOpenGl()
{
    qputenv("QT_QPA_PLATFORM", "xcb");
    qputenv("QSG_RHI_BACKEND", "opengl");
    qputenv("QT_QUICK_CONTROLS_STYLE", "Fusion");
}

// Empty when OpenGL works on this display, else why not (the test then fails with it).
inline QString openGlProblem()
{
    if (qEnvironmentVariableIsEmpty("DISPLAY"))
        return QStringLiteral("no X display (DISPLAY unset): run it under xvfb-run -a, as CTest does");
    if (QGuiApplication::platformName() != QLatin1String("xcb"))
        return QStringLiteral("the platform is %1, not xcb").arg(QGuiApplication::platformName());
    QOpenGLContext context;
    if (!context.create())
        return QStringLiteral("no OpenGL context on display %1 (Mesa's GLX missing?)").arg(qEnvironmentVariable("DISPLAY"));
    QOffscreenSurface surface;
    surface.create();
    if (!context.makeCurrent(&surface))
        return QStringLiteral("the OpenGL context cannot be made current");
    const auto *renderer = reinterpret_cast<const char *>(context.functions()->glGetString(GL_RENDERER));
    qInfo("OpenGL renderer: %s", renderer ? renderer : "?");
    context.doneCurrent();
    return {};
}

inline QString glRenderer()
{
    QOpenGLContext context;
    QOffscreenSurface surface;
    surface.create();
    if (!context.create() || !context.makeCurrent(&surface))
        return QStringLiteral("none");
    const auto *renderer = reinterpret_cast<const char *>(context.functions()->glGetString(GL_RENDERER));
    return QString::fromLatin1(renderer ? renderer : "?");
}

// The tile N46E007: 600 m of ground with a ridge along 7.5° E rising to `ridge` metres above it.
// size 1201 (SRTM3, ~90 m) or 3601 (SRTM1, ~30 m).
inline bool writeRidgeTile(const QString &folder, int size, double ridge = 400.0)
{
    const int centre = size / 2;
    const double width = (size - 1) / 40.0;  // posts: ~1.9 km east-west at 46.5° N
    return terrain::test::writeHgt(folder + QStringLiteral("/N46E007.hgt"), size, [&](int r, int c) {
        const double dc = (c - centre) / width;
        return int(600.0 + ridge * std::exp(-dc * dc) + 10.0 * std::sin(r * 0.05));
    });
}

inline mission::Waypoint waypointAt(double latitude, double longitude, double amsl)
{
    mission::Waypoint w;
    w.position = {latitude, longitude};
    w.altitude = amsl;
    w.altitudeType = mission::AltitudeType::Amsl;
    return w;
}

// Everything the view is handed, real: the ground from an SRTM tile, the route's document, the zones.
struct View3dFixture
{
    QTemporaryDir folder;
    std::unique_ptr<terrain::HgtTileSource> tiles;
    terrain::ElevationService elevation;
    client::RouteDocument document;
    std::unique_ptr<QSettings> settings;
    std::unique_ptr<airspace::Airspace> airspace;
    ui::Theme theme;
    std::unique_ptr<QuickScene> scene;

    bool prepare(int tileSize)
    {
        if (!folder.isValid() || !writeRidgeTile(folder.path(), tileSize))
            return false;
        tiles = std::make_unique<terrain::HgtTileSource>(folder.path());
        elevation.setSources({tiles.get()});
        settings = std::make_unique<QSettings>(folder.filePath(QStringLiteral("settings.ini")), QSettings::IniFormat);
        airspace = std::make_unique<airspace::Airspace>(settings.get(), document.analyzer(), document.model(), &elevation);
        return true;
    }
    bool open(QSize size)
    {
        scene = std::make_unique<QuickScene>(
            "import QtQuick\nimport Sortie.Ui\nScene3DView { objectName: \"view3d\" }\n", size,
            QVariantMap{{QStringLiteral("document"), QVariant::fromValue(&document)},
                        {QStringLiteral("airspace"), QVariant::fromValue(airspace.get())},
                        {QStringLiteral("elevation"), QVariant::fromValue(&elevation)},
                        {QStringLiteral("theme"), QVariant::fromValue(&theme)}});
        return scene->isReady();
    }
    ui::FlightScene *flightScene() const
    {
        return scene && scene->root() ? scene->root()->property("scene").value<ui::FlightScene *>() : nullptr;
    }
};

} // namespace sortie::test
