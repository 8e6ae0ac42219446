#pragma once

#include <QLoggingCategory>

// sortie.sim: the simulated UgCS server. Never logs a password.
Q_DECLARE_LOGGING_CATEGORY(lcSim)
