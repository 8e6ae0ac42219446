#include "FrameLog.h"

#include <QQuickWindow>

Q_LOGGING_CATEGORY(lcFrames, "sortie.frames", QtInfoMsg)

namespace sortie::app {

FrameLog::FrameLog(QQuickWindow *window)
    : QObject(window)
{
    if (!lcFrames().isDebugEnabled())
        return;
    // frameSwapped comes from the render thread where there is one: count on this thread.
    connect(window, &QQuickWindow::frameSwapped, this, [this] { ++m_frames; }, Qt::QueuedConnection);
    connect(&m_timer, &QTimer::timeout, this, &FrameLog::report);
    m_timer.start(1000);
}

void FrameLog::report()
{
    qCDebug(lcFrames).noquote() << "frames" << m_frames;
}

} // namespace sortie::app
