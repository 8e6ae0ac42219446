#include "EnergyFit.h"

#include "FitLog.h"

#include <cmath>
#include <map>

namespace sortie::endurance::fit {
namespace {

constexpr int64_t kMaxGapMs = 5000; // the energy across a longer gap is unknown

struct Point
{
    double x = 0; // speed or rate
    double power = 0;
};

Estimate estimateOf(const std::vector<double> &values, const QString &what, int minCount)
{
    Estimate e;
    e.count = int(values.size());
    if (values.empty()) {
        e.missing = QStringLiteral("no %1 in the logs").arg(what);
        return e;
    }
    if (e.count < minCount) {
        e.missing = QStringLiteral("too little %1: %2 samples after trimming transitions (at least %3)").arg(what).arg(e.count).arg(minCount);
        return e;
    }
    double sum = 0;
    for (double v : values)
        sum += v;
    const double mean = sum / double(values.size());
    double squares = 0;
    for (double v : values)
        squares += (v - mean) * (v - mean);
    e.value = mean;
    e.spread = values.size() > 1 ? std::sqrt(squares / double(values.size() - 1)) : kMissing;
    return e;
}

// The points near the most common x (in 0.5 m/s bins): a vehicle flown at several speeds is
// fitted at the one it flew most, within 5 %.
std::vector<Point> atMostFlown(const std::vector<Point> &points)
{
    std::map<long, int> bins;
    for (const Point &p : points)
        ++bins[std::lround(p.x * 2.0)];
    long best = 0;
    int most = 0;
    for (const auto &[bin, n] : bins)
        if (n > most)
            best = bin, most = n;
    double sum = 0;
    int n = 0;
    for (const Point &p : points)
        if (std::lround(p.x * 2.0) == best)
            sum += p.x, ++n;
    const double centre = n > 0 ? sum / n : 0.0;
    std::vector<Point> near;
    for (const Point &p : points)
        if (std::abs(p.x - centre) <= 0.05 * centre)
            near.push_back(p);
    return near;
}

// A power at a speed (or rate), both estimated from the same points.
void fitAtMostFlown(const std::vector<Point> &points, const QString &what, int minCount, Estimate *power, Estimate *x)
{
    const std::vector<Point> near = atMostFlown(points);
    std::vector<double> powers, xs;
    for (const Point &p : near)
        powers.push_back(p.power), xs.push_back(p.x);
    *power = estimateOf(powers, what, minCount);
    *x = estimateOf(xs, what, minCount);
}

} // namespace

std::optional<double> capacityOf(const FlightTrace &trace, double minFractionUsed, double *fractionUsed)
{
    // Per stretch without a long gap: trapezoids of power over time, and the remaining it took.
    const std::vector<PowerSample> &s = trace.samples;
    double energyWh = 0, fraction = 0;
    const auto closeStretch = [&](size_t begin, size_t end) {
        double first = kMissing, last = kMissing;
        for (size_t k = begin; k < end && !std::isfinite(first); ++k)
            first = s[k].remaining;
        for (size_t k = end; k > begin && !std::isfinite(last); --k)
            last = s[k - 1].remaining;
        if (std::isfinite(first) && std::isfinite(last))
            fraction += first - last;
    };
    size_t begin = 0;
    for (size_t i = 1; i < s.size(); ++i) {
        if (s[i].time - s[i - 1].time > kMaxGapMs) {
            closeStretch(begin, i);
            begin = i;
        } else if (std::isfinite(s[i - 1].powerW) && std::isfinite(s[i].powerW)) {
            energyWh += (s[i - 1].powerW + s[i].powerW) / 2.0 * double(s[i].time - s[i - 1].time) / 3.6e6;
        }
    }
    if (!s.empty())
        closeStretch(begin, s.size());
    if (fractionUsed)
        *fractionUsed = fraction;
    if (!(fraction >= minFractionUsed) || !(energyWh > 0))
        return std::nullopt;
    return energyWh / fraction;
}

EnergyFit fitEnergy(std::vector<FlightTrace> traces, const FitOptions &options)
{
    EnergyFit fit;
    // The capacity first: logs without current need it for their powers.
    std::vector<double> capacities;
    double energySum = 0, fractionSum = 0;
    for (const FlightTrace &t : traces) {
        if (!t.currentReported)
            continue;
        double fraction = 0;
        if (const auto c = capacityOf(t, options.minFractionUsed, &fraction)) {
            capacities.push_back(*c);
            energySum += *c * fraction;
            fractionSum += fraction;
        } else {
            fit.notes << QStringLiteral("%1: %2 % of the battery used, too little for its capacity (at least %3 %)")
                             .arg(t.name).arg(fraction * 100.0, 0, 'f', 1).arg(options.minFractionUsed * 100.0, 0, 'f', 0);
        }
    }
    fit.batteryWh = estimateOf(capacities, QStringLiteral("battery use"), 1);
    if (fit.batteryWh.ok()) {
        fit.batteryWh.value = energySum / fractionSum; // each flight weighted by the battery it used
        fit.capacitySource = QStringLiteral("fitted: energy used (voltage × current) / fraction of the battery used");
    } else if (options.capacityWh) {
        fit.batteryWh = {*options.capacityWh, kMissing, 0, {}};
        fit.capacitySource = QStringLiteral("given (--capacity)");
    } else {
        fit.batteryWh.missing = QStringLiteral("no log reports current and used at least %1 % of its battery; give the capacity")
                                    .arg(options.minFractionUsed * 100.0, 0, 'f', 0);
        fit.capacitySource = QStringLiteral("unknown");
    }

    std::vector<double> hover;
    std::vector<Point> level, climb, descent;
    for (FlightTrace &t : traces) {
        if (!t.currentReported) {
            if (!fit.batteryWh.ok()) {
                fit.notes << QStringLiteral("%1: no current reported and no capacity known: its powers are left out").arg(t.name);
                continue;
            }
            powersFromRemaining(t, *fit.batteryWh.value);
        }
        ++fit.flights;
        const std::vector<PhaseRun> runs = segmentPhases(t.samples, options.phases);
        for (const PhaseRun &run : runs) {
            for (size_t i = run.first; i <= run.last; ++i) {
                const PowerSample &s = t.samples[i];
                if (!std::isfinite(s.powerW))
                    continue;
                switch (run.phase) {
                case Phase::Hover: hover.push_back(s.powerW); break;
                case Phase::Level: level.push_back({s.groundSpeed, s.powerW}); break;
                case Phase::Climb: climb.push_back({s.verticalSpeed, s.powerW}); break;
                case Phase::Descent: descent.push_back({-s.verticalSpeed, s.powerW}); break;
                default: break;
                }
            }
        }
        qCDebug(lcEnduranceFit).noquote() << t.name << t.samples.size() << "samples," << runs.size() << "runs";
    }
    fit.hoverPowerW = estimateOf(hover, QStringLiteral("hover"), options.minSamples);
    fitAtMostFlown(level, QStringLiteral("level flight"), options.minSamples, &fit.cruisePowerW, &fit.cruiseSpeed);
    fitAtMostFlown(climb, QStringLiteral("straight climb"), options.minSamples, &fit.climbPowerW, &fit.climbRate);
    fitAtMostFlown(descent, QStringLiteral("straight descent"), options.minSamples, &fit.descentPowerW, &fit.descentRate);
    return fit;
}

std::optional<EnergyProfile> EnergyFit::profile(const QString &name, QString *why) const
{
    struct Figure { const char *name; const Estimate &e; };
    const Figure figures[] = {{"battery capacity", batteryWh}, {"hover power", hoverPowerW}, {"cruise power", cruisePowerW},
                              {"cruise speed", cruiseSpeed}, {"climb power", climbPowerW}, {"climb rate", climbRate},
                              {"descent power", descentPowerW}, {"descent rate", descentRate}};
    QStringList missing;
    for (const Figure &f : figures)
        if (!f.e.ok())
            missing << QStringLiteral("%1 (%2)").arg(QLatin1String(f.name), f.e.missing);
    if (!missing.isEmpty()) {
        if (why)
            *why = QStringLiteral("missing: ") + missing.join(QStringLiteral("; "));
        return std::nullopt;
    }
    EnergyProfile p;
    p.name = name;
    p.source = ProfileSource::Fit;
    p.batteryWh = *batteryWh.value;
    p.cruiseSpeed = *cruiseSpeed.value;
    p.climbRate = *climbRate.value;
    p.descentRate = *descentRate.value;
    p.hoverPowerW = *hoverPowerW.value;
    p.cruisePowerW = *cruisePowerW.value;
    p.climbPowerW = *climbPowerW.value;
    p.descentPowerW = *descentPowerW.value;
    if (const QString problem = p.problem(); !problem.isEmpty()) {
        if (why)
            *why = problem;
        return std::nullopt;
    }
    return p;
}

} // namespace sortie::endurance::fit
