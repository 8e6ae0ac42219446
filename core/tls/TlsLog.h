#pragma once

#include <QLoggingCategory>

namespace sortie::tls {
Q_DECLARE_LOGGING_CATEGORY(lcTls)
}
