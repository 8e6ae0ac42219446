#include "SimVciFleet.h"

#include "SimVciListener.h"
#include "SimVciVehicle.h"

#include <QCommandLineParser>

namespace sortie::sim {

void SimVciFleetOptions::addTo(QCommandLineParser &parser) const
{
    parser.addOptions({
        {QStringLiteral("vci"), QStringLiteral("Simulated VCI vehicles to run (default 0)."), QStringLiteral("n")},
        {QStringLiteral("vci-port"), QStringLiteral("TCP port of the first VCI vehicle on 127.0.0.1; the next ones follow (0: any free port)."),
         QStringLiteral("port"), QString::number(firstPort)},
        {QStringLiteral("vci-pty"), QStringLiteral("Also serve each VCI vehicle on a pseudo-terminal (its device name is printed).")},
        {QStringLiteral("vci-rate"), QStringLiteral("VCI telemetry NOTIFYs per second per subscribed resource."), QStringLiteral("hz"),
         QString::number(vehicle.telemetryRate)},
        {QStringLiteral("vci-time-scale"), QStringLiteral("Simulated seconds per real second."), QStringLiteral("x"),
         QString::number(vehicle.timeScale)},
        {QStringLiteral("vci-simulated-clock"), QStringLiteral("VCI vehicles stamp telemetry with their own clock (running at --vci-time-scale).")},
        {QStringLiteral("vci-content-length"), QStringLiteral("VCI vehicles frame bodies with Content-Length (default: by the JSON).")},
        {QStringLiteral("vci-answer-delay"), QStringLiteral("Test knob: VCI vehicles answer each request this late."), QStringLiteral("ms"),
         QStringLiteral("0")},
        {QStringLiteral("vci-malformed-every"), QStringLiteral("Test knob: every Nth NOTIFY goes out broken."), QStringLiteral("n"),
         QStringLiteral("0")},
        {QStringLiteral("vci-drop-after"), QStringLiteral("Test knob: close each VCI connection after sending N messages."),
         QStringLiteral("n"), QStringLiteral("0")},
    });
}

bool SimVciFleetOptions::read(const QCommandLineParser &parser, QString *error)
{
    auto integer = [&](const char *name, int min, int max, int *out) {
        if (!parser.isSet(QLatin1String(name)))
            return true;
        bool ok = false;
        const int v = parser.value(QLatin1String(name)).toInt(&ok);
        if (!ok || v < min || v > max) {
            *error = QStringLiteral("--%1 takes a whole number from %2 to %3").arg(QLatin1String(name)).arg(min).arg(max);
            return false;
        }
        *out = v;
        return true;
    };
    auto real = [&](const char *name, double min, double max, double *out) {
        if (!parser.isSet(QLatin1String(name)))
            return true;
        bool ok = false;
        const double v = parser.value(QLatin1String(name)).toDouble(&ok);
        if (!ok || v < min || v > max) {
            *error = QStringLiteral("--%1 takes a number from %2 to %3").arg(QLatin1String(name)).arg(min).arg(max);
            return false;
        }
        *out = v;
        return true;
    };
    int port = firstPort;
    if (!integer("vci", 0, 100, &count) || !integer("vci-port", 0, 65535, &port)
        || !real("vci-rate", 0.1, 1000, &vehicle.telemetryRate) || !real("vci-time-scale", 0.1, 100, &vehicle.timeScale)
        || !integer("vci-answer-delay", 0, 600000, &vehicle.answerDelayMs)
        || !integer("vci-malformed-every", 0, 1000000, &vehicle.malformedEvery)
        || !integer("vci-drop-after", 0, 100000000, &vehicle.dropAfter))
        return false;
    if (port != 0 && port + count - 1 > 65535) {
        *error = QStringLiteral("--vci-port %1 leaves no room for %2 vehicles").arg(port).arg(count);
        return false;
    }
    firstPort = quint16(port);
    pty = parser.isSet(QStringLiteral("vci-pty"));
    vehicle.simulatedClock = parser.isSet(QStringLiteral("vci-simulated-clock"));
    if (parser.isSet(QStringLiteral("vci-content-length")))
        vehicle.framing = vci::VciFraming::ContentLength;
    return true;
}

SimVciFleet::SimVciFleet(const SimVciFleetOptions &options, QObject *parent)
    : QObject(parent)
    , m_options(options)
{
    for (int i = 0; i < options.count; ++i) {
        SimVciOptions v = options.vehicle;
        v.id = QStringLiteral("vci-%1").arg(i + 1);
        v.name = QStringLiteral("Sim VCI %1").arg(i + 1);
        v.homeLatitude += 0.003 * (i % 4);  // a few hundred metres apart
        v.homeLongitude += 0.005 * (i / 4);
        m_vehicles.push_back(std::make_unique<SimVciVehicle>(v));
        m_listeners.push_back(std::make_unique<SimVciListener>(m_vehicles.back().get()));
        m_listeners.back()->setTls(options.tls);
    }
}

SimVciFleet::~SimVciFleet()
{
    m_listeners.clear(); // sessions before the vehicles they serve
}

bool SimVciFleet::start(QString *error)
{
    for (size_t i = 0; i < m_listeners.size(); ++i) {
        const quint16 port = m_options.firstPort ? quint16(m_options.firstPort + i) : 0;
        QString why;
        if (!m_listeners[i]->listen(port, &why)) {
            *error = QStringLiteral("VCI vehicle %1 cannot listen on 127.0.0.1:%2: %3").arg(i + 1).arg(port).arg(why);
            return false;
        }
        if (m_options.pty && !m_listeners[i]->openPty(&why)) {
            *error = QStringLiteral("VCI vehicle %1 cannot open a pseudo-terminal: %2").arg(i + 1).arg(why);
            return false;
        }
    }
    return true;
}

QStringList SimVciFleet::describe() const
{
    QStringList lines;
    for (size_t i = 0; i < m_listeners.size(); ++i) {
        QString line = QStringLiteral("%1 %2://127.0.0.1:%3")
                           .arg(m_vehicles[i]->options().id, m_listeners[i]->isSecure() ? QStringLiteral("vci+tls") : QStringLiteral("tcp"))
                           .arg(m_listeners[i]->port());
        if (!m_listeners[i]->ptyName().isEmpty())
            line += QStringLiteral(" serial:%1").arg(m_listeners[i]->ptyName());
        lines << line;
    }
    return lines;
}

} // namespace sortie::sim
