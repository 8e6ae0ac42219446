#include "LaunchOptions.h"

#include "CertificateFingerprint.h"
#include "DemOpener.h"
#include "PrivateFiles.h"
#include "SbsFeed.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QLoggingCategory>
#include <QDir>
#include <QStandardPaths>
#include <QUrl>
#include <QUrlQuery>

namespace sortie::app {


std::variant<VciEndpoint, QString> VciEndpoint::parse(const QString &text)
{
    const QUrl url(text.trimmed(), QUrl::StrictMode);
    if (!url.isValid() || url.scheme().isEmpty())
        return QStringLiteral("\"%1\" is not a VCI address (expected tcp://host:port or serial:///dev/ttyX?baud=57600)")
            .arg(text);
    VciEndpoint endpoint;
    if (url.scheme() == QLatin1String("tcp")) {
        endpoint.kind = Kind::Tcp;
        endpoint.host = url.host();
        if (endpoint.host.isEmpty())
            return QStringLiteral("\"%1\" has no host (expected tcp://host:port)").arg(text);
        if (url.port() <= 0)
            return QStringLiteral("\"%1\" has no port (expected tcp://host:port)").arg(text);
        endpoint.port = quint16(url.port());
        return endpoint;
    }
    if (url.scheme() == QLatin1String("vci+tls")) {
        endpoint.kind = Kind::Tcp;
        endpoint.tls = true;
        endpoint.host = url.host();
        if (endpoint.host.isEmpty() || url.port() <= 0)
            return QStringLiteral("\"%1\" needs a host and a port (expected vci+tls://host:port)").arg(text);
        endpoint.port = quint16(url.port());
        const QUrlQuery query(url);
        for (const auto &item : query.queryItems()) {
            if (item.first != QLatin1String("sha256"))
                return QStringLiteral("\"%1\": unknown option \"%2\" (only sha256 is known)").arg(text, item.first);
            const auto pin = tls::normalizedFingerprint(item.second);
            if (!pin)
                return QStringLiteral("\"%1\": sha256=%2 is not a SHA-256 fingerprint (64 hex digits)").arg(text, item.second);
            endpoint.pin = *pin;
        }
        return endpoint;
    }
    if (url.scheme() == QLatin1String("serial")) {
        endpoint.kind = Kind::Serial;
        endpoint.device = url.path();
        if (endpoint.device.isEmpty() || endpoint.device == QLatin1String("/"))
            return QStringLiteral("\"%1\" names no serial device (expected serial:///dev/ttyUSB0?baud=57600)").arg(text);
        const QUrlQuery query(url);
        for (const auto &item : query.queryItems()) {
            if (item.first != QLatin1String("baud"))
                return QStringLiteral("\"%1\": unknown serial option \"%2\" (only baud is known)").arg(text, item.first);
        }
        if (query.hasQueryItem(QStringLiteral("baud"))) {
            bool ok = false;
            const int baud = query.queryItemValue(QStringLiteral("baud")).toInt(&ok);
            if (!ok || baud <= 0)
                return QStringLiteral("\"%1\": the baud rate must be a positive number").arg(text);
            endpoint.baud = baud;
        }
        return endpoint;
    }
    return QStringLiteral("\"%1\": VCI addresses start with tcp://, vci+tls:// or serial://").arg(text);
}

QString VciEndpoint::toString() const
{
    if (kind == Kind::Tcp) {
        QString url = QStringLiteral("%1://%2:%3")
                          .arg(tls ? QStringLiteral("vci+tls") : QStringLiteral("tcp"), host.contains(QLatin1Char(':')) ? QStringLiteral("[%1]").arg(host) : host)
                          .arg(port);
        if (!pin.isEmpty())
            url += QStringLiteral("?sha256=") + QString(pin).remove(QLatin1Char(':'));
        return url;
    }
    return QStringLiteral("serial://%1?baud=%2").arg(device).arg(baud);
}

std::variant<LaunchOptions, QString> LaunchOptions::parse(const QStringList &arguments)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QCoreApplication::translate("sortie", "Sortie: mission planning and live telemetry for UgCS servers and VCI vehicles."));
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    const QCommandLineOption demo(QStringLiteral("demo"),
                                  QCoreApplication::translate("sortie", "Start the built-in simulator on this computer and connect to it."));
    const QCommandLineOption demoScene(QStringLiteral("demo-scene"),
                                       QCoreApplication::translate("sortie", "--demo with only the server's three vehicles: \"parked\" (nothing moves) or \"flying\" (one flies, followed in the fly view); for benchmarks."),
                                       QStringLiteral("scene"));
    const QCommandLineOption server(QStringLiteral("server"),
                                    QCoreApplication::translate("sortie", "UgCS server to connect to: host:port, or tls://host:port over TLS (a server behind a TLS terminator)."), QStringLiteral("host:port"));
    const QCommandLineOption serverPin(QStringLiteral("server-pin"),
                                       QCoreApplication::translate("sortie", "With --server tls://: the only certificate the server may show, as its SHA-256 fingerprint or a PEM file; remembered for that server."),
                                       QStringLiteral("sha256|file"));
    const QCommandLineOption user(QStringLiteral("user"), QCoreApplication::translate("sortie", "User name to log in with."),
                                  QStringLiteral("name"));
    const QCommandLineOption vci(QStringLiteral("vci"),
                                 QCoreApplication::translate("sortie", "Connect a vehicle directly over VCI: tcp://host:port, vci+tls://host:port[?sha256=FINGERPRINT] or serial:///dev/ttyX?baud=57600."),
                                 QStringLiteral("address"));
    const QCommandLineOption reportStartup(QStringLiteral("report-startup"),
                                           QCoreApplication::translate("sortie", "Print the start-up time and memory in use, then quit (for benchmarks)."));
    const QCommandLineOption autosave(QStringLiteral("autosave-dir"),
                                      QCoreApplication::translate("sortie", "Folder for autosaved edits (default: the application data folder; also SORTIE_AUTOSAVE_DIR)."),
                                      QStringLiteral("folder"));
    const QCommandLineOption dem(QStringLiteral("dem"),
                                 QCoreApplication::translate("sortie", "A DEM for the terrain: any raster GDAL reads (GeoTIFF, COG, Copernicus DEM, .hgt, ...) or a folder of them, asked before the server (also the setting terrain/demFolder)."),
                                 QStringLiteral("path"));
    const QCommandLineOption sbs(QStringLiteral("sbs"),
                                 QCoreApplication::translate("sortie", "An ADS-B receiver's SBS-1 feed for manned traffic, as dump1090 serves it (port 30003); also the setting traffic/sbsAddress."),
                                 QStringLiteral("host:port"));
    parser.addOptions({demo, demoScene, server, serverPin, user, vci, autosave, reportStartup, dem, sbs});

    if (!parser.parse(arguments))
        return parser.errorText();
    if (!parser.positionalArguments().isEmpty())
        return QStringLiteral("unexpected argument \"%1\" (see --help)").arg(parser.positionalArguments().first());

    LaunchOptions options;
    if (parser.isSet(help) || parser.isSet(QStringLiteral("help-all"))) {
        options.exitNow = true;
        options.output = parser.helpText();
        return options;
    }
    if (parser.isSet(version)) {
        options.exitNow = true;
        options.output = QStringLiteral("%1 %2\n").arg(QCoreApplication::applicationName(), QCoreApplication::applicationVersion());
        return options;
    }
    options.demo = parser.isSet(demo) || parser.isSet(demoScene);
    if (parser.isSet(demoScene)) {
        options.demoScene = parser.value(demoScene);
        if (options.demoScene != QLatin1String("parked") && options.demoScene != QLatin1String("flying"))
            return QStringLiteral("--demo-scene: '%1' is neither parked nor flying").arg(options.demoScene);
    }
    options.reportStartup = parser.isSet(reportStartup);
    if (parser.isSet(server)) {
        auto parsed = ServerAddress::parse(parser.value(server));
        if (auto *error = std::get_if<QString>(&parsed))
            return QStringLiteral("--server: %1").arg(*error);
        options.server = std::get<ServerAddress>(parsed);
    }
    if (options.demo && options.server)
        return QStringLiteral("--demo starts its own server: leave out --server");
    if (parser.isSet(serverPin)) {
        if (!options.server || !options.server->tls)
            return QStringLiteral("--server-pin needs --server tls://host:port");
        const auto pin = tls::pinFromArgument(QStringLiteral("--server-pin"), parser.value(serverPin));
        if (pin.index() == 1)
            return std::get<1>(pin);
        options.serverPin = std::get<0>(pin);
    }
    options.user = parser.value(user);
    options.autosaveDir = parser.value(autosave);
    options.demPath = parser.value(dem);
    if (!options.demPath.isEmpty()) {
        // A DEM that cannot be read stops the start with the file and GDAL's reason, not a silent flat world.
        QString error;
        if (!raster::openDem(options.demPath, &error))
            return QStringLiteral("--dem: %1").arg(error);
    }
    if (parser.isSet(sbs)) {
        QString host;
        quint16 port = 0;
        if (!traffic::SbsFeed::parseAddress(parser.value(sbs), &host, &port))
            return QStringLiteral("--sbs: '%1' is not host:port").arg(parser.value(sbs));
        options.sbsAddress = parser.value(sbs).trimmed();
    }
    if (parser.isSet(vci)) {
        auto parsed = VciEndpoint::parse(parser.value(vci));
        if (auto *error = std::get_if<QString>(&parsed))
            return QStringLiteral("--vci: %1").arg(*error);
        options.vci = std::get<VciEndpoint>(parsed);
    }
    return options;
}

namespace {

Q_LOGGING_CATEGORY(lcLaunch, "sortie.launch", QtInfoMsg)

// The demo's private folder, made once a run: never a fixed name in the shared temporary folder,
// where another local user could make it first, read the routes, plant autosaves, hold the locks.
QString demoFolder()
{
    static const QString folder = [] {
        QString error;
        const QString made = files::privateRuntimeFolder(QStringLiteral("sortie-demo"), &error);
        if (made.isEmpty())
            qCWarning(lcLaunch).noquote() << "demo:" << error;
        return made;
    }();
    return folder;
}

// The environment's folder, else the demo's own, else one in the application data folder.
QString dataFolder(const char *variable, const QString &name, bool demo)
{
    const QString env = qEnvironmentVariable(variable);
    if (!env.isEmpty())
        return env;
    if (demo && !demoFolder().isEmpty())
        return QDir(demoFolder()).filePath(name);
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(name);
}

} // namespace

client::ClientGraph::Options LaunchOptions::graphOptions() const
{
    client::ClientGraph::Options graph;
    graph.demFolder = demPath;
    graph.sbsAddress = sbsAddress;
    graph.autosaveDirectory = autosaveDir.isEmpty() ? dataFolder("SORTIE_AUTOSAVE_DIR", QStringLiteral("autosave"), demo) : autosaveDir;
    graph.flightLogDirectory = dataFolder("SORTIE_FLIGHTLOG_DIR", QStringLiteral("flightlogs"), demo);
    graph.zoneFeedDirectory = dataFolder("SORTIE_ZONE_FEED_DIR", QStringLiteral("zone-feeds"), demo);
    // The checklists are the operator's to edit: beside the settings, not the data.
    const QString checklists = qEnvironmentVariable("SORTIE_CHECKLIST_DIR");
    graph.checklistDirectory = !checklists.isEmpty()           ? checklists
                               : demo && !demoFolder().isEmpty() ? QDir(demoFolder()).filePath(QStringLiteral("checklists"))
                                                                 : QDir(QStandardPaths::writableLocation(QStandardPaths::AppConfigLocation)).filePath(QStringLiteral("checklists"));
    return graph;
}

} // namespace sortie::app
