#include "NoElevationSource.h"
