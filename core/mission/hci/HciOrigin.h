#pragma once

#include <memory>

namespace com::ugcs::ucs::proto {
class SegmentDefinition;
class Route;
class Mission;
}

namespace sortie::mission {

// The protobuf object a value came from, kept beside it so that saving merges our edits into a
// copy of what the server sent (unknown fields included). Provenance, not content: two values
// that differ only in origin compare equal.
template<typename Message>
struct HciOrigin
{
    std::shared_ptr<const Message> message;
    bool operator==(const HciOrigin &) const { return true; }
    explicit operator bool() const { return bool(message); }
};

using SegmentOrigin = HciOrigin<com::ugcs::ucs::proto::SegmentDefinition>;
using RouteOrigin = HciOrigin<com::ugcs::ucs::proto::Route>;
using MissionOrigin = HciOrigin<com::ugcs::ucs::proto::Mission>;

} // namespace sortie::mission
