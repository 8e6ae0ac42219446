#include "HciOrigin.h"

#include "Domain.pb.h"

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;

const pb::SegmentDefinition *hciSegment(const ServerOrigin &origin) { return hciMessage<pb::SegmentDefinition>(origin); }
const pb::Route *hciRoute(const ServerOrigin &origin) { return hciMessage<pb::Route>(origin); }
const pb::Mission *hciMission(const ServerOrigin &origin) { return hciMessage<pb::Mission>(origin); }

} // namespace sortie::mission
