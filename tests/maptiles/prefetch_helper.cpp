// A prefetch in a process of its own, for tst_tileprefetch to kill mid-way:
// prefetch_helper <url template> <file> <min zoom> <max zoom> <south> <west> <north> <east>
#include "TilePrefetch.h"

#include <QCoreApplication>
#include <QNetworkAccessManager>

using namespace sortie::maptiles;

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() != 9)
        return 2;
    QNetworkAccessManager network;
    PrefetchPlan plan{TileUrlTemplate(args[1]),
                      TileArea::rectangle({args[5].toDouble(), args[6].toDouble(), args[7].toDouble(), args[8].toDouble()}),
                      args[3].toInt(), args[4].toInt(), args[2], {}, QStringLiteral("Test tiles")};
    PrefetchLimits limits;
    limits.batchSize = 4;
    limits.flushIntervalMs = 50;
    TilePrefetch job(&network, plan, limits);
    QObject::connect(&job, &TilePrefetch::finished, &app, &QCoreApplication::quit);
    if (!job.start())
        return 1;
    return app.exec();
}
