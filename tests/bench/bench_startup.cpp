// Start-up of the real client program: `sortie --report-startup`, offscreen with the software
// renderer and fresh settings, started N times. The time is taken here, from starting the process
// to reading its "first-frame" line (the login view is on screen and takes input), so it includes
// loading the program and its libraries. Also prints the resident memory at that frame and after
// three idle seconds, alone and with --demo (logged in to the in-process simulator).
//
// Usage: bench_startup [runs]   (default 10)

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

struct Run
{
    double wallMs = -1;   // process start to the first frame, measured here
    double insideMs = -1; // main() to the first frame, as the program measured it
    double frameRssMiB = 0;
    double idleRssMiB = 0;
};

Run launch(const QStringList &arguments)
{
    QTemporaryDir home;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    env.insert(QStringLiteral("QT_QUICK_BACKEND"), QStringLiteral("software"));
    env.insert(QStringLiteral("QT_LOGGING_RULES"), QStringLiteral("sortie.*.info=false"));
    env.insert(QStringLiteral("HOME"), home.path());
    env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
    env.insert(QStringLiteral("XDG_DATA_HOME"), home.filePath(QStringLiteral("data")));
    env.insert(QStringLiteral("XDG_CACHE_HOME"), home.filePath(QStringLiteral("cache")));
    QProcess process;
    process.setProcessEnvironment(env);
    process.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    Run run;
    QElapsedTimer clock;
    clock.start();
    process.start(QStringLiteral(SORTIE_APP_PATH), QStringList{QStringLiteral("--report-startup")} + arguments);
    QByteArray output;
    static const QRegularExpression first(QStringLiteral("first-frame (\\d+) ms, rss (\\d+) KiB"));
    static const QRegularExpression idle(QStringLiteral("idle rss (\\d+) KiB"));
    while (process.state() != QProcess::NotRunning || process.bytesAvailable() > 0) {
        if (!process.waitForReadyRead(30000) && process.bytesAvailable() == 0)
            break;
        output += process.readAllStandardOutput();
        const auto m = first.match(QString::fromLatin1(output));
        if (m.hasMatch() && run.wallMs < 0) {
            run.wallMs = double(clock.nsecsElapsed()) / 1e6;
            run.insideMs = m.captured(1).toDouble();
            run.frameRssMiB = m.captured(2).toDouble() / 1024;
        }
        const auto i = idle.match(QString::fromLatin1(output));
        if (i.hasMatch()) {
            run.idleRssMiB = i.captured(1).toDouble() / 1024;
            break;
        }
    }
    process.waitForFinished(10000);
    return run;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}

bool series(const char *what, const QStringList &arguments, int runs)
{
    std::vector<double> wall, inside, frameRss, idleRss;
    for (int i = 0; i < runs; ++i) {
        const Run r = launch(arguments);
        if (r.wallMs < 0 || r.idleRssMiB <= 0) {
            std::printf("%s: run %d FAILED (no report from sortie)\n", what, i + 1);
            return false;
        }
        wall.push_back(r.wallMs);
        inside.push_back(r.insideMs);
        frameRss.push_back(r.frameRssMiB);
        idleRss.push_back(r.idleRssMiB);
    }
    std::printf("%-34s first frame: median %6.0f ms (min %4.0f, max %4.0f; from main() %4.0f ms)   RSS at first frame %5.1f MiB,"
                " idle %5.1f MiB\n",
                what, median(wall), *std::min_element(wall.begin(), wall.end()), *std::max_element(wall.begin(), wall.end()),
                median(inside), median(frameRss), median(idleRss));
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const int runs = argc > 1 ? std::max(1, atoi(argv[1])) : 10;
    std::printf("bench_startup: %d runs each of %s --report-startup, offscreen, software renderer\n", runs, SORTIE_APP_PATH);
    bool ok = series("login view", {}, runs);
    ok = series("--demo (simulator in-process)", {QStringLiteral("--demo")}, runs) && ok;
    return ok ? 0 : 1;
}
