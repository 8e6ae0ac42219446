#include "HciSimOptions.h"

#include "HciMessageTypes.h"
#include "TlsServerIdentity.h"

#include <QCommandLineParser>
#include <QFile>

namespace sortie::sim {
namespace {

bool readInt(const QCommandLineParser &p, const QString &name, int min, int max, int *out, QString *error)
{
    if (!p.isSet(name))
        return true;
    bool ok = false;
    const int v = p.value(name).toInt(&ok);
    if (!ok || v < min || v > max) {
        *error = QStringLiteral("--%1: expected a whole number from %2 to %3, got '%4'").arg(name).arg(min).arg(max).arg(p.value(name));
        return false;
    }
    *out = v;
    return true;
}

// A request type by number ("64") or name ("SendCommandRequest").
bool readTypes(const QCommandLineParser &p, const QString &name, QSet<int> *out, QString *error)
{
    for (const QString &value : p.values(name)) {
        bool ok = false;
        int type = value.toInt(&ok);
        if (!ok) {
            const auto byName = hci::HciMessageTypes::numberOf(value.toStdString());
            ok = byName.has_value();
            type = byName.value_or(-1);
        }
        if (!ok) {
            *error = QStringLiteral("--%1: '%2' is neither a message type number nor a message name").arg(name, value);
            return false;
        }
        out->insert(type);
    }
    return true;
}

} // namespace

HciSimOptions::HciSimOptions()
{
    m_options = {
        {QStringLiteral("port"), QStringLiteral("HCI port (default 3334; 0 picks a free one)."), QStringLiteral("port")},
        {QStringLiteral("listen"), QStringLiteral("Address to listen on (default 127.0.0.1)."), QStringLiteral("address")},
        {QStringLiteral("user"), QStringLiteral("An account, login:password (repeatable; default admin:admin)."), QStringLiteral("login:password")},
        {QStringLiteral("hci-vehicles"), QStringLiteral("Number of emulator vehicles EMU-101... (default 3)."), QStringLiteral("n")},
        {QStringLiteral("store"), QStringLiteral("Keep the objects in this JSON file (loaded at start, saved on change)."), QStringLiteral("file")},
        {QStringLiteral("dem"), QStringLiteral("The ground from a DEM: any raster GDAL reads (GeoTIFF, .hgt, ...) or a folder of them; default: built-in hills near Riga."),
         QStringLiteral("path")},
        {QStringLiteral("telemetry-rate"), QStringLiteral("Telemetry rate in Hz (default 10)."), QStringLiteral("hz")},
        {QStringLiteral("session-expiry"), QStringLiteral("Seconds a disconnected session can be re-attached (default 60)."), QStringLiteral("s")},
        {QStringLiteral("max-sessions"), QStringLiteral("Licence limit on logged-in sessions (default none)."), QStringLiteral("n")},
        {QStringLiteral("no-demo-mission"), QStringLiteral("Do not create the demo mission and route.")},
        {QStringLiteral("energy-profile"), QStringLiteral("Every simulated vehicle's battery and powers from this energy profile (JSON; default: docs/endurance-fit.md)."),
         QStringLiteral("file")},
        {QStringLiteral("tls-cert"), QStringLiteral("Serve TLS (HCI and VCI) with this PEM certificate; needs --tls-key."), QStringLiteral("file")},
        {QStringLiteral("tls-key"), QStringLiteral("The PEM private key of --tls-cert (unencrypted)."), QStringLiteral("file")},
        {QStringLiteral("fault-reverse"), QStringLiteral("Test: hold answers until N wait, then send them newest first."), QStringLiteral("n")},
        {QStringLiteral("fault-delay"), QStringLiteral("Test: delay every answer by this many ms."), QStringLiteral("ms")},
        {QStringLiteral("fault-drop"), QStringLiteral("Test: never answer this request type (number or name; repeatable)."), QStringLiteral("type")},
        {QStringLiteral("fault-malformed"), QStringLiteral("Test: send a malformed frame before each of the next N answers."), QStringLiteral("n")},
        {QStringLiteral("fault-disconnect-on"), QStringLiteral("Test: drop the connection when this request type arrives (repeatable)."), QStringLiteral("type")},
    };
}

void HciSimOptions::addTo(QCommandLineParser &parser) const
{
    parser.addOptions(m_options);
}

bool HciSimOptions::read(const QCommandLineParser &p, QString *error)
{
    int portValue = port;
    if (!readInt(p, QStringLiteral("port"), 0, 65535, &portValue, error))
        return false;
    port = quint16(portValue);
    if (p.isSet(QStringLiteral("listen")) && !address.setAddress(p.value(QStringLiteral("listen")))) {
        *error = QStringLiteral("--listen: '%1' is not an IP address").arg(p.value(QStringLiteral("listen")));
        return false;
    }
    for (const QString &spec : p.values(QStringLiteral("user"))) {
        const auto user = SimUsers::parse(spec);
        if (!user) {
            *error = QStringLiteral("--user: expected login:password");
            return false;
        }
        world.users.append(*user);
    }
    int seconds = sessionExpiryMs / 1000;
    if (!readInt(p, QStringLiteral("hci-vehicles"), 0, 1000, &world.vehicles, error)
        || !readInt(p, QStringLiteral("session-expiry"), 1, 86400, &seconds, error)
        || !readInt(p, QStringLiteral("max-sessions"), 0, 10000, &world.maxSessions, error)
        || !readInt(p, QStringLiteral("fault-reverse"), 0, 1000, &faults.reverseBatch, error)
        || !readInt(p, QStringLiteral("fault-delay"), 0, 600000, &faults.delayMs, error)
        || !readInt(p, QStringLiteral("fault-malformed"), 0, 1000000, &faults.malformedBeforeAnswers, error)
        || !readTypes(p, QStringLiteral("fault-drop"), &faults.dropAnswersTo, error)
        || !readTypes(p, QStringLiteral("fault-disconnect-on"), &faults.disconnectOn, error))
        return false;
    sessionExpiryMs = seconds * 1000;
    if (p.isSet(QStringLiteral("telemetry-rate"))) {
        bool ok = false;
        world.telemetryRateHz = p.value(QStringLiteral("telemetry-rate")).toDouble(&ok);
        if (!ok || world.telemetryRateHz < 0 || world.telemetryRateHz > 100) {
            *error = QStringLiteral("--telemetry-rate: expected a rate from 0 to 100 Hz");
            return false;
        }
    }
    world.storePath = p.value(QStringLiteral("store"));
    world.demPath = p.value(QStringLiteral("dem"));
    world.demoMission = !p.isSet(QStringLiteral("no-demo-mission"));
    if (p.isSet(QStringLiteral("energy-profile"))) {
        QFile file(p.value(QStringLiteral("energy-profile")));
        if (!file.open(QIODevice::ReadOnly)) {
            *error = QStringLiteral("--energy-profile: %1: %2").arg(file.fileName(), file.errorString());
            return false;
        }
        const auto profile = endurance::readEnergyProfile(file.readAll());
        if (!profile) {
            *error = QStringLiteral("--energy-profile: %1: %2").arg(file.fileName(), profile.error().toString());
            return false;
        }
        world.energy = *profile;
    }
    const bool cert = p.isSet(QStringLiteral("tls-cert")), key = p.isSet(QStringLiteral("tls-key"));
    if (cert != key) {
        *error = cert ? QStringLiteral("--tls-cert needs --tls-key") : QStringLiteral("--tls-key needs --tls-cert");
        return false;
    }
    if (cert) {
        QString why;
        tls = tls::loadServerIdentity(p.value(QStringLiteral("tls-cert")), p.value(QStringLiteral("tls-key")), &why);
        if (!tls) {
            *error = QStringLiteral("--tls-cert/--tls-key: %1").arg(why);
            return false;
        }
    }
    return true;
}

} // namespace sortie::sim
