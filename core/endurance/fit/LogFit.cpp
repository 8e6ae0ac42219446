#include "LogFit.h"

#include "FitLog.h"
#include "FlightLog.h"

#include <QFileInfo>

#include <cmath>

namespace sortie::endurance::fit {

LoadedFlights loadFlights(const QStringList &paths, const QString &vehicle)
{
    LoadedFlights loaded;
    for (const QString &path : paths) {
        QString error;
        const auto log = flightlog::FlightLog::open(path, &error);
        if (!log) {
            loaded.failures << error;
            continue;
        }
        if (const QString damage = log->damage(); !damage.isEmpty())
            loaded.warnings << QStringLiteral("%1 is damaged: %2").arg(path, damage);
        int used = 0;
        for (int v = 0; v < int(log->vehicles().size()); ++v) {
            const flightlog::FlightLog::Vehicle &info = log->vehicles()[size_t(v)];
            if (!vehicle.isEmpty() && info.name() != vehicle && info.key != vehicle)
                continue;
            FlightTrace trace = traceOf(*log, v);
            if (trace.samples.empty()) {
                loaded.warnings << QStringLiteral("%1: %2 reports neither battery current nor remaining").arg(path, info.name());
                continue;
            }
            loaded.traces.push_back(std::move(trace));
            ++used;
        }
        if (used == 0 && !vehicle.isEmpty())
            loaded.warnings << QStringLiteral("%1: no vehicle \"%2\" with battery telemetry").arg(path, vehicle);
        qCInfo(lcEnduranceFit).noquote() << path << ":" << used << "vehicle(s) to fit";
    }
    return loaded;
}

namespace {

QString figure(const char *label, const Estimate &e, const char *unit, int precision, const char *counted = "n = ")
{
    const QString head = QStringLiteral("%1").arg(QLatin1String(label), -16);
    if (!e.ok())
        return head + QStringLiteral("missing: ") + e.missing;
    const QString spread = std::isfinite(e.spread) ? QStringLiteral("± %1").arg(e.spread, 0, 'f', precision) : QStringLiteral("± —");
    return head + QStringLiteral("%1 %2 %3 (%4%5)").arg(*e.value, 8, 'f', precision).arg(QLatin1String(unit), -3).arg(spread, -9)
                      .arg(QLatin1String(counted)).arg(e.count);
}

} // namespace

QString fitReport(const EnergyFit &fit)
{
    QStringList lines;
    lines << QStringLiteral("Fitted from %1 flight(s); spread is the standard deviation, n the samples.").arg(fit.flights);
    lines << figure("hover power", fit.hoverPowerW, "W", 1);
    lines << figure("cruise power", fit.cruisePowerW, "W", 1);
    lines << figure("cruise speed", fit.cruiseSpeed, "m/s", 2);
    lines << figure("climb power", fit.climbPowerW, "W", 1);
    lines << figure("climb rate", fit.climbRate, "m/s", 2);
    lines << figure("descent power", fit.descentPowerW, "W", 1);
    lines << figure("descent rate", fit.descentRate, "m/s", 2);
    lines << figure("battery", fit.batteryWh, "Wh", 1, "flights: ");
    lines << QStringLiteral("capacity: ") + fit.capacitySource;
    for (const QString &note : fit.notes)
        lines << QStringLiteral("note: ") + note;
    return lines.join(u'\n') + u'\n';
}

} // namespace sortie::endurance::fit
