#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace google::protobuf {
class Descriptor;
class Message;
} // namespace google::protobuf

namespace sortie::hci {

// The one table that maps HCI message type numbers to protobuf message types, both ways.
class HciMessageTypes
{
public:
    // The default instance of the message mapped to `number`, or nullptr when none is.
    static const google::protobuf::Message *prototype(int32_t number);
    // The type number of a message type, or nullopt when it is not an HCI message.
    static std::optional<int32_t> number(const google::protobuf::Descriptor *descriptor);
    // The message's name (e.g. "LoginRequest"), or empty when the number is not mapped.
    static std::string_view name(int32_t number);
    // The type number of a message by name ("LoginResponse"), or nullopt.
    static std::optional<int32_t> numberOf(std::string_view name);
    // The dedicated response to a request type (LoginRequest -> LoginResponse), or nullopt when the
    // request has none (e.g. CheckPermissionRequest, answered by EmptyResponse or Error).
    static std::optional<int32_t> responseFor(int32_t requestNumber);

    static size_t count();
    static int32_t numberAt(size_t index);
};

} // namespace sortie::hci
