#pragma once

#include "ComparisonController.h"
#include "PhotoSurvey.h"
#include "RecordingSettings.h"
#include "ReplayController.h"
#include "ServerHistoryRequest.h"

#include <QtQml/qqmlregistration.h>

namespace sortie::ui {

// The replay's core objects under names QML views can type their properties with; the
// application makes them, QML never does.
struct ReplayControllerForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::flightlog::ReplayController)
    QML_NAMED_ELEMENT(ReplayController)
    QML_UNCREATABLE("The application provides the replay controller.")
};

struct ReplayEventModelForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::flightlog::ReplayEventModel)
    QML_NAMED_ELEMENT(ReplayEventModel)
    QML_UNCREATABLE("Part of the replay controller.")
};

struct ReplayFleetForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::flightlog::ReplayFleet)
    QML_NAMED_ELEMENT(ReplayFleet)
    QML_UNCREATABLE("Part of the replay controller.")
};

struct ComparisonControllerForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::flightlog::ComparisonController)
    QML_NAMED_ELEMENT(ComparisonController)
    QML_UNCREATABLE("The application provides the comparison.")
};

struct ServerHistoryRequestForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::flightlog::ServerHistoryRequest)
    QML_NAMED_ELEMENT(ServerHistoryRequest)
    QML_UNCREATABLE("The application provides the server history request.")
};

struct PhotoSurveyForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::coverage::PhotoSurvey)
    QML_NAMED_ELEMENT(PhotoSurvey)
    QML_UNCREATABLE("The application provides the photo survey.")
};

struct RecordingSettingsForeign
{
    Q_GADGET
    QML_FOREIGN(sortie::flightlog::RecordingSettings)
    QML_NAMED_ELEMENT(RecordingSettings)
    QML_UNCREATABLE("The application provides the recording settings.")
};

} // namespace sortie::ui
