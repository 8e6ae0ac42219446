// Flight log reader (.sortielog, an SQLite file): any bytes, written to a file, are opened and read
// through, or refused with a reason; a log read gives every series and its thinned form without a
// crash, whatever its blocks, events and routes hold; a photo event is a photo on the globe or none.
#include "FlightLog.h"
#include "PhotoEvents.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>

#include <cmath>
#include <cstdlib>
#include <unistd.h>

using namespace sortie::flightlog;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int argc = 1;
    static char name[] = "fuzz_sortielog";
    static char *argv[] = {name, nullptr};
    static QCoreApplication app(argc, argv);  // the SQL driver is a plugin
    static const QString path = QDir::temp().filePath(QStringLiteral("fuzz-%1.sortielog").arg(getpid()));
    {
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
            std::abort();
        file.write(reinterpret_cast<const char *>(data), qint64(size));
    }
    QString error;
    const std::unique_ptr<FlightLog> log = FlightLog::open(path, &error);
    if (!log) {
        if (error.isEmpty())
            std::abort();
        return 0;
    }
    for (int v = 0; v < int(log->vehicles().size()); ++v) {
        for (int f = 0; f < int(sortie::vehicle::kTelemetryFieldCount); ++f)
            log->series(v, sortie::vehicle::TelemetryField(f));
        log->thinnedSeries(v, 50);
        log->stateAt(v, log->end());
        for (const sortie::vehicle::CameraPhoto &p : photosOf(*log, v))
            if (p.sequence < 1 || !(std::abs(p.latitude) <= 90) || !(std::abs(p.longitude) <= 180))
                std::abort();
    }
    return 0;
}
