#include "PreflightLog.h"

Q_LOGGING_CATEGORY(lcPreflight, "sortie.preflight")
