#pragma once

#include <QElapsedTimer>
#include <QObject>

class QQuickWindow;

namespace sortie::app {

// --report-startup: when the first frame of the main window (the login view, ready for input) is
// on screen, prints "first-frame <ms since main> ms, rss <KiB> KiB"; after `idleMs` more of doing
// nothing, prints "idle rss <KiB> KiB" and quits. bench_startup reads these lines.
class StartupProbe : public QObject
{
    Q_OBJECT

public:
    StartupProbe(QQuickWindow *window, QElapsedTimer sinceMain, int idleMs = 3000);

private:
    void firstFrame();

    QElapsedTimer m_sinceMain;
    int m_idleMs;
    bool m_seen = false;
};

} // namespace sortie::app
