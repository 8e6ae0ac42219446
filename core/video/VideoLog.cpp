#include "VideoLog.h"

Q_LOGGING_CATEGORY(lcVideo, "sortie.video")
