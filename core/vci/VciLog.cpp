#include "VciLog.h"

Q_LOGGING_CATEGORY(lcVci, "sortie.vci")
