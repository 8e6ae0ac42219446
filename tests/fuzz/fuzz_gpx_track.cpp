// GPX tracks (sortie-log geotag --track FILE.gpx): any bytes, written to a file, are a track or
// refused with a reason that names the file; a track read is in time order with one point a time,
// every latitude and longitude in range, and a photo placed on it anywhere gets a position inside
// the box of its points or a reason.
#include "Geotagger.h"
#include "Track.h"

#include <QDir>
#include <QFile>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <unistd.h>

using namespace sortie::geotag;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const QString path = QDir::temp().filePath(QStringLiteral("fuzz-%1.gpx").arg(getpid()));
    {
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
            std::abort();
        file.write(reinterpret_cast<const char *>(data), qint64(size));
    }
    QString error;
    const auto track = readGpxTrack(path, &error);
    if (!track) {
        if (!error.startsWith(path))
            std::abort();
        return 0;
    }
    if (track->points.empty())
        std::abort();
    double south = 90, north = -90;
    for (size_t i = 0; i < track->points.size(); ++i) {
        const TrackPoint &p = track->points[i];
        if (!(std::fabs(p.latitude) <= 90) || !(std::fabs(p.longitude) <= 180))
            std::abort();
        if (i > 0 && p.time <= track->points[i - 1].time)
            std::abort();
        south = std::min(south, p.latitude);
        north = std::max(north, p.latitude);
    }
    const int64_t span = track->end() - track->start();
    for (const int64_t t : {track->start() - 1, track->start(), track->start() + span / 3, track->end(), track->end() + 1}) {
        QString reason;
        const auto position = positionAt(*track, t, 5000, &reason);
        if (!position && reason.isEmpty())
            std::abort();
        if (position && (position->latitude < south - 1e-9 || position->latitude > north + 1e-9 || !(std::fabs(position->longitude) <= 180)))
            std::abort();
    }
    return 0;
}
