#include "SceneGraphChoice.h"

#include <QDir>
#include <QElapsedTimer>
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

// A GPU an OpenGL driver could use: a DRM device (Mesa's drivers, nvidia-drm), NVIDIA's own, or
// WSL's. Without one, Mesa can only draw on the CPU, and asking OpenGL (which loads Mesa, 50 MB,
// and took 100-200 ms under Xvfb) would only say so. A GPU behind another device: QSG_RHI_BACKEND=opengl.
bool hasGpuDevice()
{
    const auto filters = QDir::System | QDir::NoDotAndDotDot;
    return !QDir(QStringLiteral("/dev/dri")).entryList(filters).isEmpty()
        || !QDir(QStringLiteral("/dev")).entryList({QStringLiteral("nvidia[0-9]*"), QStringLiteral("dxg")}, filters).isEmpty();
}

bool drawnByTheCpu(const QString &renderer)
{
    for (const char *software : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})  // i18n: not text (renderer names)
        if (renderer.contains(QLatin1String(software), Qt::CaseInsensitive))
            return true;
    return false;
}

} // namespace

void chooseSceneGraph()
{
    if (qEnvironmentVariableIsSet("QT_QUICK_BACKEND") || qEnvironmentVariableIsSet("QSG_RHI_BACKEND"))
        return;
    if (!hasGpuDevice()) {
        QQuickWindow::setGraphicsApi(QSGRendererInterface::Software);
        qCInfo(lcSceneGraph).noquote() << "drawing with the software scene graph: no GPU device (/dev/dri, /dev/nvidia*)";
        return;
    }
    QElapsedTimer asking;
    asking.start();
    const QString renderer = openGlRenderer();
    const qint64 ms = asking.elapsed();
    if (!drawnByTheCpu(renderer)) {
        qCDebug(lcSceneGraph).noquote() << "OpenGL renderer" << (renderer.isEmpty() ? QStringLiteral("none") : renderer)
                                        << "(asked in" << ms << "ms)";
        return;
    }
    QQuickWindow::setGraphicsApi(QSGRendererInterface::Software);
    qCInfo(lcSceneGraph).noquote() << "drawing with the software scene graph: OpenGL would be" << renderer
                                   << "(asked in" << ms << "ms)";
}

} // namespace sortie::app
