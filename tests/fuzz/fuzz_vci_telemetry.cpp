// The VCI telemetry mapping (VciTelemetryMapper.h): any JSON body of any profile resource becomes
// telemetry or nothing. Every value is a known field with a finite value, and every time is the
// body's own (when an int64 holds it) or the one given. The first byte chooses the resource.
#include "VciProfile.h"
#include "VciTelemetryMapper.h"

#include <array>
#include <cmath>
#include <cstdlib>

using namespace sortie;
namespace profile = sortie::vci::profile;

namespace {
const std::array<std::string_view, 18> kResources = {
    profile::kVehicle, profile::kPosition, profile::kAttitude, profile::kSpeed, profile::kBattery, profile::kGps,
    profile::kHome, profile::kArmed, profile::kMode, profile::kTakeoff, profile::kLand, profile::kReturnHome,
    profile::kGoto, profile::kMission, profile::kMissionProgress, profile::kParameters, profile::kFenceStatus, profile::kFence,
};
constexpr int64_t kNow = 1764670000000;
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    const std::string_view uri = kResources[data[0] % kResources.size()];
    const auto body = nlohmann::json::parse(data + 1, data + size, nullptr, false);
    if (body.is_discarded())
        return 0;
    const vehicle::TelemetryBatch batch = vehicle::vciTelemetry(uri, body, kNow);
    for (const vehicle::TelemetryUpdate &u : batch) {
        if (u.field >= vehicle::TelemetryField::Count_ || !std::isfinite(u.value))
            std::abort();
        const auto t = body.is_object() ? body.find("time") : body.end();
        if ((!body.is_object() || t == body.end() || !t->is_number()) && u.time != kNow)
            std::abort();
    }
    return 0;
}
