#include "TerrainLog.h"

Q_LOGGING_CATEGORY(lcTerrain, "sortie.terrain")
