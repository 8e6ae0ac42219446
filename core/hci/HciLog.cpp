#include "HciLog.h"

Q_LOGGING_CATEGORY(lcHci, "sortie.hci", QtInfoMsg)
