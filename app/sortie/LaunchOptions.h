#pragma once

#include "ClientGraph.h"
#include "ServerAddress.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <variant>

namespace sortie::app {

using client::ServerAddress;

// Where a VCI vehicle is: tcp://host:port, vci+tls://host:port[?sha256=PIN] or serial:///dev/ttyX?baud=57600.
struct VciEndpoint
{
    enum class Kind { Tcp, Serial };
    Kind kind = Kind::Tcp;
    QString host;       // Tcp
    quint16 port = 0;   // Tcp
    bool tls = false;   // Tcp over TLS (vci+tls://)
    QString pin;        // vci+tls://...?sha256=: the vehicle's certificate, colon-hex
    QString device;     // Serial
    qint32 baud = 57600; // Serial

    static std::variant<VciEndpoint, QString> parse(const QString &text);
    QString toString() const;
};

// What the command line asked for. --help and --version are answered by parse() through
// `output` (the text to print) with `exitNow` set.
struct LaunchOptions
{
    bool demo = false;
    // --demo-scene: what moves in the demo (implies --demo): "parked" (the server's three vehicles
    // on the ground, nothing else) or "flying" (one of them flying, followed in the fly view); empty: everything.
    QString demoScene;
    std::optional<ServerAddress> server;
    // --server-pin: the SHA-256 of the only certificate --server (tls://) may show, from a
    // fingerprint or a PEM certificate file; pinned in the settings for that server.
    QString serverPin;
    QString user;
    std::optional<VciEndpoint> vci;
    bool reportStartup = false; // print start-up time and memory, then quit
    QString autosaveDir; // --autosave-dir; empty: SORTIE_AUTOSAVE_DIR, else the default
    QString demPath;     // --dem: a DEM file or folder for the terrain; empty: the setting terrain/demFolder
    QString sbsAddress;  // --sbs: an ADS-B receiver's SBS-1 feed, host:port; empty: the setting traffic/sbsAddress

    bool exitNow = false;
    QString output;

    // Errors come back as one line an operator understands.
    static std::variant<LaunchOptions, QString> parse(const QStringList &arguments);

    // The client graph the program builds for these options: the terrain folder, and where autosaves
    // and flight logs go (--autosave-dir, else SORTIE_AUTOSAVE_DIR; SORTIE_FLIGHTLOG_DIR; else a folder
    // of the demo's own, whose server lives only as long as the program; else the application data folder).
    client::ClientGraph::Options graphOptions() const;
};

} // namespace sortie::app
