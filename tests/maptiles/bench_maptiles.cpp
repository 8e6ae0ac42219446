// Offline maps, measured: how long the tile count of an area takes (rectangles in closed form,
// polygons row by row) and how many tiles a second the MBTiles writer stores (20 kB tiles, in
// transactions of 32 as the prefetch job writes them). Prints its figures (docs/performance.md).
#include "MbTilesFile.h"
#include "TileArea.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>

using namespace sortie::maptiles;

namespace {
template <typename F>
double millisecondsPerCall(F &&call, int repeats)
{
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < repeats; ++i)
        call();
    return clock.nsecsElapsed() / 1e6 / repeats;
}
} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    // A 10 km × 10 km survey block and a 40-corner polygon of the same size.
    const GeoBounds block = GeoBounds{56.90, 24.00, 56.99, 24.165};
    const TileArea rectangle = TileArea::rectangle(block);
    QList<QPointF> corners;
    for (int i = 0; i < 40; ++i) {
        const double a = 2 * M_PI * i / 40, r = (i % 2 ? 0.6 : 1.0);
        corners.append({24.08 + 0.08 * r * std::cos(a), 56.945 + 0.045 * r * std::sin(a)});
    }
    const TileArea polygon = TileArea::polygon(corners);
    for (const int maxZoom : {16, 18, 20}) {
        qint64 count = 0;
        const double rectMs = millisecondsPerCall([&] { count = rectangle.tileCount(10, maxZoom); }, 200);
        std::printf("count rectangle 10 km, zoom 10-%d: %lld tiles in %.4f ms\n", maxZoom, count, rectMs);
        const double polyMs = millisecondsPerCall([&] { count = polygon.tileCount(10, maxZoom); }, maxZoom >= 20 ? 3 : 20);
        std::printf("count 40-corner polygon, zoom 10-%d: %lld tiles in %.3f ms\n", maxZoom, count, polyMs);
    }

    QTemporaryDir dir;
    MbTilesFile file;
    QString error;
    if (!file.open(dir.filePath(QStringLiteral("bench.mbtiles")), MbTilesFile::Mode::ReadWrite, &error)) {
        std::printf("cannot open: %s\n", qPrintable(error));
        return 1;
    }
    QByteArray tile(20000, Qt::Uninitialized);
    for (char &c : tile)
        c = char(QRandomGenerator::global()->bounded(256));
    const int batches = 200, batchSize = 32;
    QElapsedTimer clock;
    clock.start();
    int written = 0;
    for (int b = 0; b < batches; ++b) {
        QList<MbTilesFile::Tile> batch;
        for (int i = 0; i < batchSize; ++i, ++written)
            batch.append({{16, 36000 + written % 512, 20000 + written / 512}, tile});
        if (!file.writeTiles(batch, &error)) {
            std::printf("write failed: %s\n", qPrintable(error));
            return 1;
        }
    }
    const double seconds = clock.nsecsElapsed() / 1e9;
    std::printf("writer: %d tiles of 20 kB in batches of %d: %.0f tiles/s (%.1f MB/s)\n", written, batchSize, written / seconds,
                written * 20000.0 / 1e6 / seconds);
    clock.restart();
    const QSet<quint64> stored = file.storedTiles(0, 24);
    std::printf("resume scan: %lld stored tiles listed in %.1f ms\n", qint64(stored.size()), clock.nsecsElapsed() / 1e6);
    return 0;
}
