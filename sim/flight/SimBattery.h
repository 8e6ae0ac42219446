#pragma once

namespace sortie::sim {

// A simulated LiPo pack as an energy store: drained by the power drawn over time; its voltage is
// the open-circuit voltage of its state of charge less the sag of the load across its internal
// resistance, and the current is the power over that voltage. Pure C++.
class SimBattery
{
public:
    static constexpr int kCells = 4;
    static constexpr double kInternalOhms = 0.025; // the whole pack

    explicit SimBattery(double capacityWh);

    // Draws `powerW` for `dt` seconds (the load stays until the next draw: voltage and current follow it).
    void draw(double powerW, double dt);

    double capacityWh() const { return m_capacityWh; }
    double energyLeftWh() const { return m_energyWh; }
    double remaining() const { return m_energyWh / m_capacityWh; } // 0..1
    double voltage() const { return m_voltage; }                    // V, under the present load
    double current() const { return m_current; }                    // A

    // Open-circuit voltage of one cell at a state of charge (0..1): a typical LiPo discharge curve,
    // 4.20 V full, a plateau around 3.8 V, 3.27 V empty.
    static double cellVoltage(double stateOfCharge);

private:
    void settle(double powerW);

    double m_capacityWh;
    double m_energyWh;
    double m_voltage = 0;
    double m_current = 0;
};

} // namespace sortie::sim
