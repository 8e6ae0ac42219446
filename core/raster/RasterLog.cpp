#include "RasterLog.h"

Q_LOGGING_CATEGORY(lcRaster, "sortie.raster")
