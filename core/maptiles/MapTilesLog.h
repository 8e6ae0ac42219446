#pragma once

#include <QLoggingCategory>

namespace sortie::maptiles {
Q_DECLARE_LOGGING_CATEGORY(lcMapTiles) // "sortie.maptiles": prefetch jobs, retries, refused tiles
}
