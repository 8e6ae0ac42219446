#include "StartupProbe.h"

#include <QCoreApplication>
#include <QFile>
#include <QQuickWindow>
#include <QTimer>

#include <cstdio>

namespace sortie::app {

namespace {
qint64 residentKiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').value(0).toLongLong();
    }
    return -1;
}
} // namespace

StartupProbe::StartupProbe(QQuickWindow *window, QElapsedTimer sinceMain, int idleMs)
    : QObject(window)
    , m_sinceMain(sinceMain)
    , m_idleMs(idleMs)
{
    connect(window, &QQuickWindow::frameSwapped, this, &StartupProbe::firstFrame);
}

void StartupProbe::firstFrame()
{
    if (m_seen)
        return;
    m_seen = true;
    std::printf("first-frame %lld ms, rss %lld KiB\n", static_cast<long long>(m_sinceMain.elapsed()), static_cast<long long>(residentKiB()));
    std::fflush(stdout);
    QTimer::singleShot(m_idleMs, this, [] {
        std::printf("idle rss %lld KiB\n", static_cast<long long>(residentKiB()));
        std::fflush(stdout);
        QCoreApplication::quit();
    });
}

} // namespace sortie::app
