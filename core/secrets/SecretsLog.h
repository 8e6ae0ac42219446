#pragma once

#include <QLoggingCategory>

// Keyring reachability and which entry was read, written or removed; never a password.
Q_DECLARE_LOGGING_CATEGORY(lcSecrets) // "sortie.secrets"
