#include "SimLog.h"

Q_LOGGING_CATEGORY(lcSim, "sortie.sim", QtInfoMsg)
