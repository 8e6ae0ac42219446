// Time to autosave a 10,000-waypoint route: encoding (.sortie of the working route, spliced into
// the autosave with the cached baseline) and the atomic write (QSaveFile: write, flush, fsync,
// rename; then fsync of the folder), and the whole RouteAutosave::writeNow(). Prints medians.
#include "AtomicFile.h"
#include "AutosaveRecord.h"
#include "RouteAutosave.h"
#include "RouteDocument.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <vector>

using namespace sortie;

namespace {

double medianMs(int runs, const std::function<void()> &work)
{
    std::vector<double> times;
    for (int i = 0; i < runs; ++i) {
        QElapsedTimer t;
        t.start();
        work();
        times.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    constexpr int kWaypoints = 10000;
    mission::Route route;
    route.settings.name = QStringLiteral("Bench 10k");
    for (int i = 0; i < kWaypoints; ++i) {
        mission::Waypoint w;
        w.position = {56.9 + 0.0001 * (i % 100), 24.1 + 0.0001 * (i / 100)};
        w.altitude = 40 + i % 30;
        if (i % 10 == 0)
            w.actions.push_back(mission::WaitAction{2, false});
        route.segments.push_back(w);
    }
    QTemporaryDir dir;
    client::RouteDocument doc;
    client::RouteAutosave autosave(&doc, dir.path());
    doc.load(route);
    doc.editor()->setAltitude({5}, 99);

    const QByteArray baseline = client::encodeAutosaveRoute(doc.route());
    client::AutosaveRecord header;
    header.savedAt = QDateTime::currentDateTimeUtc();
    QByteArray data;
    const double encode = medianMs(15, [&] { data = client::encodeAutosave(header, client::encodeAutosaveRoute(doc.route()), baseline); });
    const QString path = dir.filePath(QStringLiteral("plain.json"));
    const double write = medianMs(15, [&] { client::writeFileAtomically(path, data); });
    const double whole = medianMs(15, [&] { autosave.writeNow(); });
    std::printf("autosave of a %d-waypoint route (%.1f MB):\n", kWaypoints, data.size() / 1e6);
    std::printf("  encode (working route; baseline cached): %8.1f ms (median of 15)\n", encode);
    std::printf("  atomic write (write, fsync, rename, fsync dir): %8.1f ms (median of 15)\n", write);
    std::printf("  RouteAutosave::writeNow, all of it:     %8.1f ms (median of 15)\n", whole);
    return 0;
}
