#include "TrafficLog.h"

Q_LOGGING_CATEGORY(lcTraffic, "sortie.traffic")
