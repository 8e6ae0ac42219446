#pragma once

#include <QLoggingCategory>

// sortie.hci: connection, session and client calls. Never log a password or a whole LoginRequest.
Q_DECLARE_LOGGING_CATEGORY(lcHci)
