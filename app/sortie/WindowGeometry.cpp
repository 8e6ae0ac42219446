#include "WindowGeometry.h"

#include "AppSettings.h"

#include <QGuiApplication>
#include <QScreen>
#include <QWindow>

namespace sortie::app {

void restoreWindowGeometry(QWindow &window, const ui::AppSettings &settings)
{
    const QRect geometry = settings.windowGeometry();
    if (geometry.isValid()) {
        for (const QScreen *screen : QGuiApplication::screens()) {
            if (screen->availableGeometry().intersects(geometry)) {
                window.setGeometry(geometry);
                break;
            }
        }
    }
    if (settings.windowMaximized())
        window.setWindowStates(Qt::WindowMaximized);
}

void saveWindowGeometry(const QWindow &window, ui::AppSettings &settings)
{
    const bool maximized = window.windowStates() & (Qt::WindowMaximized | Qt::WindowFullScreen);
    settings.setWindowMaximized(maximized);
    if (!maximized)
        settings.setWindowGeometry(window.geometry());
    settings.sync();
}

} // namespace sortie::app
