#pragma once

#include "FlightModel.h"
#include "VciFence.h"

#include <optional>

namespace sortie::sim {

// The fence a simulated VCI vehicle keeps (docs/vci-profile.md, "Fence"): after each tick it is
// asked whether the vehicle, airborne, is outside every inclusion item or inside an exclusion item
// between its floor and ceiling. A breach is counted when it begins, and its breach action is what
// the vehicle should do then; the status says whether it is breached now.
class SimFence
{
public:
    const vci::profile::Fence &fence() const { return m_fence; }
    uint64_t version() const { return m_version; }
    void set(vci::profile::Fence fence);

    // The action to take when a breach began with this state; nullopt otherwise.
    std::optional<vci::profile::BreachAction> check(const FlightModel::State &state);
    vci::profile::FenceStatus status(int64_t time) const;

    // Where the state is against one item, horizontally and in height (for tests and check()).
    static bool insideHorizontally(const vci::profile::FenceItem &item, double latitude, double longitude);
    static bool betweenLimits(const vci::profile::FenceItem &item, double altitudeAmsl, double aboveHome);

private:
    vci::profile::Fence m_fence;
    uint64_t m_version = 0;
    bool m_breached = false;
    int m_breaches = 0;
    int m_item = -1;
    std::string m_kind;
    std::string m_action;
};

} // namespace sortie::sim
