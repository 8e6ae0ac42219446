#pragma once

namespace sortie::sim {

class HciRequestDispatcher;
class SimTraffic;

// The ADS-B aircraft the simulated server knows, for logged-in clients: GetAdsbAircraftListRequest
// answered with the world's traffic (SimTraffic) within `radius` metres of `location` (radians, as
// everywhere in HCI); `height` is not used: the simulated receiver hears every height. Each
// AdsbAircraft carries its address, call sign (identification), position (radians), mslAltitude,
// heading (radians), groundSpeed and verticalVelocity (m/s) and updateTime (now, ms since the epoch).
class SimTrafficService
{
public:
    static void install(HciRequestDispatcher &dispatcher, const SimTraffic &traffic);
};

} // namespace sortie::sim
