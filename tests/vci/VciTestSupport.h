#pragma once

// Test helpers: a simulated VCI vehicle on loopback, and a callback that records its result.
#include "SimVciListener.h"
#include "SimVciSession.h"
#include "SimVciVehicle.h"
#include "VciConnection.h"

#include <memory>

namespace sortie::vci::test {

struct Capture
{
    bool done = false;
    int calls = 0;
    VciResult result;
    VciConnection::Callback callback()
    {
        return [this](const VciResult &r) {
            done = true;
            ++calls;
            result = r;
        };
    }
};

struct SimVehicle
{
    explicit SimVehicle(sim::SimVciOptions options = {})
        : vehicle(std::make_unique<sim::SimVciVehicle>(options))
        , listener(std::make_unique<sim::SimVciListener>(vehicle.get()))
    {
    }
    sim::SimVciSession *session() const
    {
        const auto all = listener->sessions();
        return all.isEmpty() ? nullptr : all.first();
    }
    std::unique_ptr<sim::SimVciVehicle> vehicle;
    std::unique_ptr<sim::SimVciListener> listener;
};

// Degrees to the profile's radians.
inline double rad(double degrees) { return degrees * 3.14159265358979323846 / 180.0; }

} // namespace sortie::vci::test
