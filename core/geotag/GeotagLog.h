#pragma once

#include <QLoggingCategory>

// sortie.geotag: photos' metadata read and written, tracks read, photos matched to them.
Q_DECLARE_LOGGING_CATEGORY(lcGeotag)
