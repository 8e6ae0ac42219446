#include "FitLog.h"

Q_LOGGING_CATEGORY(lcEnduranceFit, "sortie.endurance.fit", QtInfoMsg)
