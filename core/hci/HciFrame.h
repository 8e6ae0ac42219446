#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace google::protobuf {
class Message;
}

namespace sortie::hci {

// Wire constants of the HCI packet header: 16 bytes, big-endian.
inline constexpr uint16_t kHciSignature = 0x4850; // "HP"
inline constexpr uint16_t kHciVersion = 1;
inline constexpr size_t kHciHeaderSize = 16;
inline constexpr int64_t kHciMaxPayload = 64LL * 1024 * 1024; // exactly 64 MiB is allowed
inline constexpr int32_t kHciNotificationInstance = -1;

struct HciFrameHeader
{
    uint16_t signature = kHciSignature;
    uint16_t version = kHciVersion;
    int32_t instanceId = 0;
    int32_t type = 0;
    int32_t length = 0;

    static HciFrameHeader read(const char *bytes);
    void write(char *out) const;
    bool plausible() const; // right signature and version, a mapped type, a sane length
};

inline HciFrameHeader HciFrameHeader::read(const char *b)
{
    const auto *u = reinterpret_cast<const unsigned char *>(b);
    auto u16 = [u](int i) { return uint16_t(u[i] << 8 | u[i + 1]); };
    auto i32 = [u](int i) { return int32_t(uint32_t(u[i]) << 24 | uint32_t(u[i + 1]) << 16 | uint32_t(u[i + 2]) << 8 | u[i + 3]); };
    return {u16(0), u16(2), i32(4), i32(8), i32(12)};
}

inline void HciFrameHeader::write(char *out) const
{
    auto put16 = [&out](uint16_t v) { *out++ = char(v >> 8); *out++ = char(v); };
    auto put32 = [&out](int32_t s) {
        const auto v = uint32_t(s);
        *out++ = char(v >> 24); *out++ = char(v >> 16); *out++ = char(v >> 8); *out++ = char(v);
    };
    put16(signature);
    put16(version);
    put32(instanceId);
    put32(type);
    put32(length);
}

// Why a frame was dropped. Every reason but BadLength consumes exactly the frame's bytes.
enum class HciDropReason {
    BadSignature,   // signature is not 0x4850
    BadVersion,     // version is not 1
    UnknownType,    // no message is mapped to the type number
    InvalidPayload, // the payload is not valid protobuf for the mapped message
    MissingRequired,// a proto2 required field is missing
    BadLength,      // the length is negative or over 64 MiB: the decoder resynchronises (docs/protocols.md)
    TooLarge,       // the payload would decode into more than kHciMaxDecodedBytes (HciDecodedSize.h)
};

const char *toString(HciDropReason reason);

// One decoded frame: the header, its byte offset in the stream, and the parsed message.
struct HciFrame
{
    uint64_t offset = 0;
    HciFrameHeader header;
    std::unique_ptr<google::protobuf::Message> message;
};

// One dropped frame, with the reason an operator or developer can read.
struct HciDroppedFrame
{
    uint64_t offset = 0;
    HciFrameHeader header;
    HciDropReason reason = HciDropReason::InvalidPayload;
    std::string detail;
    uint64_t bytesDiscarded = 0;
};

} // namespace sortie::hci
