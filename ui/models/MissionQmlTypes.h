#pragma once

// The editing types QML views use beside the ones ui/qmltypes registers: the enums the
// RouteEditor takes (MissionEnums.Amsl, MissionEnums.Continuing) and the generated segment
// editor's model, the waypoint actions' model and their field rows.
#include "MissionEnums.h"
#include "SegmentEditorModel.h"
#include "WaypointActionsModel.h"

#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

namespace MissionEnumsForeign {
Q_NAMESPACE
QML_FOREIGN_NAMESPACE(sortie::mission::MissionEnums)
QML_NAMED_ELEMENT(MissionEnums)
} // namespace MissionEnumsForeign

struct SegmentEditorModelForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::mission::SegmentEditorModel)
    QML_NAMED_ELEMENT(SegmentEditorModel)
    QML_UNCREATABLE("the document's, handed to the views")
};

struct WaypointActionsModelForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::mission::WaypointActionsModel)
    QML_NAMED_ELEMENT(WaypointActionsModel)
    QML_UNCREATABLE("the document's, handed to the views")
};

// A field row the action editor holds by type (`property actionFieldRow row`), read by property.
struct ActionFieldRowForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::mission::ActionFieldRow)
    QML_VALUE_TYPE(actionFieldRow)
};

} // namespace sortie::ui
