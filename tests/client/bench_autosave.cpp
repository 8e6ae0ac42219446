// Time to autosave a 10,000-waypoint route, split by thread. The GUI thread's share: the snapshot
// (a copy of the route value) and the hand-off to the writer (RouteAutosave::writeLater, what the
// timer does after a batch of edits), and what saving costs it (the baseline snapshot). The
// writer thread's share: encoding (.sortie of the working route, spliced into the autosave with
// the cached baseline) and the atomic write (QSaveFile: write, flush, fsync, rename; then fsync of
// the folder). Prints medians of 15.
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
#include <optional>
#include <vector>

using namespace sortie;

namespace {

constexpr int kRuns = 15;

// `prepare` runs before each timed `work`, untimed.
double medianMs(const std::function<void()> &work, const std::function<void()> &prepare = {})
{
    std::vector<double> times;
    for (int i = 0; i < kRuns; ++i) {
        if (prepare)
            prepare();
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
    autosave.setDelay(60 * 60 * 1000); // the bench queues the writes itself
    doc.load(route);
    int edits = 0;
    auto edit = [&] { doc.editor()->setAltitude({5}, 60 + edits++ % 20); };
    edit();
    autosave.waitForWriter();

    // GUI thread.
    // A snapshot is freed by the writer once written, so the next one mostly reuses its memory;
    // the first one after a load, or one taken while 15 are kept, touches fresh pages.
    std::optional<mission::Route> copy;
    const double snapshot = medianMs([&] { copy.emplace(doc.route()); }, [&] { copy.reset(); });
    std::vector<mission::Route> copies;
    copies.reserve(kRuns);
    const double freshSnapshot = medianMs([&] { copies.push_back(doc.route()); });
    copies.clear();
    const double handOff = medianMs([&] { autosave.writeLater(); }, [&] { autosave.waitForWriter(); edit(); });
    const double save = medianMs([&] { doc.markSaved(); }, [&] { autosave.waitForWriter(); edit(); });
    edit();

    // Writer thread.
    const QByteArray baseline = client::encodeAutosaveRoute(doc.route());
    client::AutosaveRecord header;
    header.savedAt = QDateTime::currentDateTimeUtc();
    QByteArray data;
    const double encode = medianMs([&] { data = client::encodeAutosave(header, client::encodeAutosaveRoute(doc.route()), baseline); });
    const QString path = dir.filePath(QStringLiteral("plain.json"));
    const double write = medianMs([&] { client::writeFileAtomically(path, data); });
    // From the hand-off until the writer is done with it (the worker's share, as wall time).
    const double worker = medianMs([&] { autosave.waitForWriter(); }, [&] { autosave.waitForWriter(); edit(); autosave.writeLater(); });
    const double whole = medianMs([&] { autosave.writeNow(); }, [&] { edit(); });

    std::printf("autosave of a %d-waypoint route (%.1f MB), medians of %d:\n", kWaypoints, data.size() / 1e6, kRuns);
    std::printf("GUI thread:\n");
    std::printf("  snapshot (copy of the route value):                  %8.2f ms\n", snapshot);
    std::printf("  snapshot into fresh memory (15 copies kept):         %8.2f ms\n", freshSnapshot);
    std::printf("  RouteAutosave::writeLater (header, snapshot, queue):  %8.2f ms\n", handOff);
    std::printf("  saving: markSaved (baseline snapshot, removal queued): %7.2f ms\n", save);
    std::printf("writer thread:\n");
    std::printf("  encode (working route; baseline cached):             %8.1f ms\n", encode);
    std::printf("  atomic write (write, fsync, rename, fsync dir):      %8.1f ms\n", write);
    std::printf("  hand-off to done (encode + write on the worker):     %8.1f ms\n", worker);
    std::printf("both (RouteAutosave::writeNow waits for the writer):   %8.1f ms\n", whole);
    return 0;
}
