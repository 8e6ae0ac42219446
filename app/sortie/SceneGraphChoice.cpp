#include "SceneGraphChoice.h"

#include <QLoggingCategory>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QQuickWindow>
#include <QSGRendererInterface>

Q_LOGGING_CATEGORY(lcSceneGraph, "sortie.scenegraph", QtInfoMsg)

namespace sortie::app {

namespace {

// The OpenGL renderer's name ("llvmpipe (LLVM 15.0.6, 256 bits)"), empty when there is no OpenGL.
QString openGlRenderer()
{
    QOpenGLContext context;
    if (!context.create())
        return {};
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    if (!surface.isValid() || !context.makeCurrent(&surface))
        return {};
    const auto *name = reinterpret_cast<const char *>(context.functions()->glGetString(GL_RENDERER));
    const QString renderer = name ? QString::fromLatin1(name) : QString();
    context.doneCurrent();
    return renderer;
}

bool drawnByTheCpu(const QString &renderer)
{
    for (const char *software : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})
        if (renderer.contains(QLatin1String(software), Qt::CaseInsensitive))
            return true;
    return false;
}

} // namespace

void chooseSceneGraph()
{
    if (qEnvironmentVariableIsSet("QT_QUICK_BACKEND") || qEnvironmentVariableIsSet("QSG_RHI_BACKEND"))
        return;
    const QString renderer = openGlRenderer();
    if (!drawnByTheCpu(renderer)) {
        qCDebug(lcSceneGraph).noquote() << "OpenGL renderer" << (renderer.isEmpty() ? QStringLiteral("none") : renderer);
        return;
    }
    QQuickWindow::setGraphicsApi(QSGRendererInterface::Software);
    qCInfo(lcSceneGraph).noquote() << "drawing with the software scene graph: OpenGL would be" << renderer;
}

} // namespace sortie::app
