#pragma once

// The theme's QML name (ui/theme is a room of its own, below the module). Creatable: a view shown
// on its own, with no window to hand it one (a dialog in a test), makes one that follows the system.
#include "Theme.h"

#include <QtQml/qqmlregistration.h>

namespace sortie::ui::qmltypes {

struct ThemeForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::ui::Theme)
    QML_NAMED_ELEMENT(Theme)
};

} // namespace sortie::ui::qmltypes
