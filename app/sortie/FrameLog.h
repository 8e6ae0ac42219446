#pragma once

#include <QLoggingCategory>
#include <QObject>
#include <QTimer>

class QQuickWindow;

Q_DECLARE_LOGGING_CATEGORY(lcFrames)

namespace sortie::app {

// Counts the frames the main window puts on screen (QQuickWindow::frameSwapped) and, while the
// logging category sortie.frames is enabled for debug (QT_LOGGING_RULES="sortie.frames.debug=true"),
// writes "frames <total>" once a second. scripts/bench-idle.sh reads these lines; off, it costs one
// connection and no timer.
class FrameLog : public QObject
{
    Q_OBJECT

public:
    explicit FrameLog(QQuickWindow *window);

private:
    void report();

    qint64 m_frames = 0;
    QTimer m_timer;
};

} // namespace sortie::app
