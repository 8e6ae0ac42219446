#include "SimBattery.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace sortie::sim {

SimBattery::SimBattery(double capacityWh)
    : m_capacityWh(capacityWh > 0 ? capacityWh : 1.0)
    , m_energyWh(m_capacityWh)
{
    settle(0);
}

double SimBattery::cellVoltage(double stateOfCharge)
{
    // Every 10 % from empty to full.
    static constexpr std::array<double, 11> kCurve{3.27, 3.61, 3.69, 3.73, 3.77, 3.80, 3.85, 3.91, 3.98, 4.08, 4.20};
    const double x = std::clamp(stateOfCharge, 0.0, 1.0) * 10.0;
    const size_t i = std::min(size_t(x), kCurve.size() - 2);
    return kCurve[i] + (kCurve[i + 1] - kCurve[i]) * (x - double(i));
}

void SimBattery::draw(double powerW, double dt)
{
    m_energyWh = std::max(0.0, m_energyWh - std::max(0.0, powerW) * dt / 3600.0);
    settle(powerW);
}

void SimBattery::settle(double powerW)
{
    // V = OCV − R·I with I = P/V: the larger root of V² − OCV·V + R·P = 0. A load the pack cannot
    // deliver (no real root) leaves it at the voltage of its largest power.
    const double ocv = kCells * cellVoltage(remaining());
    const double load = std::max(0.0, powerW);
    const double d = ocv * ocv - 4.0 * kInternalOhms * load;
    m_voltage = d > 0 ? (ocv + std::sqrt(d)) / 2.0 : ocv / 2.0;
    m_current = load / m_voltage;
}

} // namespace sortie::sim
