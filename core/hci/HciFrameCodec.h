#pragma once

#include "HciFrame.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace sortie::hci {

// Encodes one frame: header + protobuf payload. Returns false (and appends nothing) when the
// message is not an HCI message or a required field is missing, so a peer never sees a frame
// it would have to drop.
bool appendHciFrame(std::string &out, int32_t instanceId, const google::protobuf::Message &message);
std::optional<std::string> encodeHciFrame(int32_t instanceId, const google::protobuf::Message &message);
// Frames an already serialised payload under an explicit type number (tests, tools, fault injection).
std::string encodeRawHciFrame(int32_t instanceId, int32_t type, std::string_view payload,
                              uint16_t signature = kHciSignature, uint16_t version = kHciVersion);

// A whole frame as delimited by the stream, not yet decoded (HciFrameDecoder::takeWhole).
struct HciRawFrame
{
    uint64_t offset = 0;
    HciFrameHeader header;
    std::string payload;
};

// Incremental HCI decoder: feed bytes in chunks of any size, take frames out in stream order.
// Pure: no I/O, no Qt objects. Frames are delimited by the length field, as UgCS does; a frame
// that cannot be used is consumed and reported with its reason, and decoding goes on. A length
// below 0 or above 64 MiB cannot delimit anything: it is reported and the decoder scans for the
// next plausible header (see docs/protocols.md). Memory is bounded by what has arrived: nothing is
// reserved from an untrusted length.
class HciFrameDecoder
{
public:
    using Result = std::variant<HciFrame, HciDroppedFrame>;

    HciFrameDecoder();
    ~HciFrameDecoder(); // out of line: the spare messages are of a type this header only declares
    HciFrameDecoder(HciFrameDecoder &&) noexcept;
    HciFrameDecoder &operator=(HciFrameDecoder &&) noexcept;

    void feed(std::string_view bytes);
    // The next frame, decoded or dropped, or nullopt when more bytes are needed.
    std::optional<Result> next();
    // Hands a decoded message back for reuse: the next frame of the same type is parsed into it, which
    // keeps its sub-messages and string capacity (telemetry arrives at thousands of frames a second).
    void recycle(std::unique_ptr<google::protobuf::Message> message);
    // Takes the next frame undecoded when it has arrived whole and its payload is at least
    // `minimumLength` bytes (nothing otherwise: next() deals with it), so that a big frame can be
    // decoded on another thread with decode(). Frames taken so are not counted by this decoder.
    std::optional<HciRawFrame> takeWhole(size_t minimumLength);
    // Decodes a frame taken whole: the same checks and drop reasons as next(). Touches no decoder,
    // so it may run on any thread.
    static Result decode(const HciRawFrame &frame);

    size_t buffered() const { return m_buffer.size() - m_pos; }
    // The bytes fed but not yet consumed (an incomplete frame), e.g. to report a truncated capture.
    std::string_view pending() const { return std::string_view(m_buffer).substr(m_pos); }
    uint64_t streamOffset() const { return m_offset; }
    uint64_t framesDecoded() const { return m_decoded; }
    uint64_t framesDropped() const { return m_dropped; }
    // Bytes skipped while resynchronising after a bad length (the bad header itself included).
    uint64_t bytesDiscarded() const { return m_discarded; }
    void reset();
    // Telemetry notifications take a direct parser (HciTelemetryFastPath) unless this is off; the
    // result is the same either way. Off is for comparing the two.
    void setFastPath(bool enabled) { m_fastPath = enabled; }

private:
    bool resynchronise();
    std::unique_ptr<google::protobuf::Message> take(const google::protobuf::Message &prototype);

    HciDroppedFrame drop(const HciFrameHeader &header, HciDropReason reason, std::string detail);

    std::string m_buffer;
    size_t m_pos = 0;       // first unread byte in m_buffer
    uint64_t m_offset = 0;  // stream offset of m_buffer[m_pos]
    bool m_resyncing = false;
    uint64_t m_decoded = 0;
    uint64_t m_dropped = 0;
    uint64_t m_discarded = 0;
    bool m_fastPath = true;
    // A few spare messages, at most kSpares, most recently recycled last.
    static constexpr size_t kSpares = 4;
    std::vector<std::unique_ptr<google::protobuf::Message>> m_spares;
};

} // namespace sortie::hci
