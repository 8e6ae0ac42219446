#include "MissionLog.h"

Q_LOGGING_CATEGORY(lcMission, "sortie.mission")
