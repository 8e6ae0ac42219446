#include "SavedRouteMerge.h"

#include <variant>

namespace sortie::mission {

Route overSavedRoute(Route current, const Route &sent, const Route &saved)
{
    current.origin = saved.origin;
    // The server stores the segments it was sent, in order; a stored list of another length says
    // it did something else, and then no segment can be matched with confidence.
    if (sent.segments.size() != saved.segments.size())
        return current;
    std::vector<bool> taken(sent.segments.size(), false);
    for (Segment &segment : current.segments) {
        for (size_t i = 0; i < sent.segments.size(); ++i) {
            if (taken[i] || !(sent.segments[i] == segment)) // == leaves origins out
                continue;
            taken[i] = true;
            const ServerOrigin &origin = originOf(saved.segments[i]);
            std::visit([&origin](auto &value) { value.origin = origin; }, segment);
            break;
        }
    }
    return current;
}

} // namespace sortie::mission
