#include "TlsLog.h"

namespace sortie::tls {
Q_LOGGING_CATEGORY(lcTls, "sortie.tls")
}
