// A Sortie-like process for the kill -9 tests: a RouteDocument with RouteAutosave running.
//   autosave_helper <dir> edit <expected.sortie>   the test edits, exports the edited route to
//                                                  <expected.sortie>, prints "AUTOSAVED <file>"
//                                                  once the autosave is written, then idles.
//   autosave_helper <dir> burst                    edits without pause, autosaving after each
//                                                  edit; prints "BURSTING" after the first write.
#include "AutosaveTestRoute.h"
#include "RouteAutosave.h"

#include <QGeoCoordinate>
#include <QCoreApplication>
#include <QTimer>
#include <QUrl>

#include <cstdio>

using namespace sortie;

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    if (args.size() < 3)
        return 2;
    client::RouteDocument doc;
    client::RouteAutosave autosave(&doc, args[1]);
    if (!autosave.isActive()) {
        std::fprintf(stderr, "%s\n", qPrintable(autosave.error()));
        return 1;
    }
    autosave.setServer(QStringLiteral("127.0.0.1:3334"), QStringLiteral("admin"));
    doc.load(test::serverRoute());

    if (args[2] == QLatin1String("edit") && args.size() == 4) {
        autosave.setDelay(50);
        QObject::connect(&autosave, &client::RouteAutosave::written, [](const QString &path) {
            std::printf("AUTOSAVED %s\n", qPrintable(path));
            std::fflush(stdout);
        });
        test::editRoute(doc);
        if (!doc.exportFile(QUrl::fromLocalFile(args[3])))
            return 1;
        return app.exec();
    }
    if (args[2] == QLatin1String("burst")) {
        QTimer edits;
        int step = 0;
        QObject::connect(&edits, &QTimer::timeout, [&] {
            // Grow the route, so every write is bigger than the one before, and write at once.
            doc.editor()->addWaypoint(QGeoCoordinate(56.9 + 0.0001 * (step % 1000), 24.1 + 0.0001 * (step / 1000)));
            if (!autosave.writeNow())
                QCoreApplication::exit(1);
            if (step++ == 0) {
                std::printf("BURSTING\n");
                std::fflush(stdout);
            }
        });
        edits.start(0);
        return app.exec();
    }
    return 2;
}
