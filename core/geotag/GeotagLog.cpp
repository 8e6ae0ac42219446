#include "GeotagLog.h"

Q_LOGGING_CATEGORY(lcGeotag, "sortie.geotag", QtInfoMsg)
