#include "SecretsLog.h"

Q_LOGGING_CATEGORY(lcSecrets, "sortie.secrets", QtInfoMsg)
