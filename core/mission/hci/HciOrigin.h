#pragma once

#include "ServerOrigin.h"

#include <memory>

namespace com::ugcs::ucs::proto {
class SegmentDefinition;
class Route;
class Mission;
}

namespace sortie::mission {

// What an origin holds when the HCI mapping filled it: the protobuf message the server sent.
template<typename Message>
struct HciPayload final : ServerOrigin::Payload
{
    explicit HciPayload(Message m) : message(std::move(m)) {}
    const Message message;
};

// An origin holding `message` (a SegmentDefinition, a Route or a Mission as the server sent it).
template<typename Message>
ServerOrigin hciOrigin(Message message)
{
    return ServerOrigin(std::make_shared<const HciPayload<Message>>(std::move(message)));
}

// The message an origin holds, or nullptr when it holds none of that type.
template<typename Message>
const Message *hciMessage(const ServerOrigin &origin)
{
    const auto *payload = dynamic_cast<const HciPayload<Message> *>(origin.payload());
    return payload ? &payload->message : nullptr;
}

// The same for the three kinds of origin the HCI mapping fills (defined where their type is complete).
const com::ugcs::ucs::proto::SegmentDefinition *hciSegment(const ServerOrigin &origin);
const com::ugcs::ucs::proto::Route *hciRoute(const ServerOrigin &origin);
const com::ugcs::ucs::proto::Mission *hciMission(const ServerOrigin &origin);

} // namespace sortie::mission
