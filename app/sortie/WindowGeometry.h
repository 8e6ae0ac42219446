#pragma once

class QWindow;

namespace sortie::ui {
class AppSettings;
}

namespace sortie::app {

// Puts the window where it was last time (if that place is still on a screen) and remembers
// where it is when the application quits.
void restoreWindowGeometry(QWindow &window, const ui::AppSettings &settings);
void saveWindowGeometry(const QWindow &window, ui::AppSettings &settings);

} // namespace sortie::app
