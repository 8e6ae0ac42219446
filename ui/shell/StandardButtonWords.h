#pragma once

class QObject;

namespace sortie::ui {

// A dialog's standard buttons ("OK", "Cancel") in the language now in use. Qt 6.4's DialogButtonBox
// words them once, when made, and not again on a language change: this re-words every standard
// button under `root` (a window) with Qt's own words (QPlatformTheme's, from qtbase_<lang>.qm),
// keeping the button and whatever is bound to it (an OK button's `enabled`).
void rewordStandardButtons(QObject *root);

} // namespace sortie::ui
