#pragma once

#include "MissionEnums.h"

#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// The enums the RouteEditor takes, for QML: MissionEnums.Amsl, MissionEnums.Continuing, ...
struct MissionEnumsForeign
{
    Q_GADGET
    QML_FOREIGN_NAMESPACE(sortie::mission::MissionEnums)
    QML_NAMED_ELEMENT(MissionEnums)
};

} // namespace sortie::ui
