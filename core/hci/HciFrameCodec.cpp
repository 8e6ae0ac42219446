#include "HciFrameCodec.h"

#include "HciDecodedSize.h"

#include "HciMessageTypes.h"
#include "HciTelemetryFastPath.h"
#include "Messages.pb.h"

#include <google/protobuf/message.h>

#include <cstring>
#include <typeinfo>

namespace sortie::hci {
namespace {
constexpr int32_t kNotificationType = 1;

// Why a big payload is not parsed: it would decode into more memory than one frame may take.
std::optional<std::string> decodedSizeProblem(const google::protobuf::Message &prototype, std::string_view payload)
{
    if (payload.size() < kHciPrescanFromBytes)
        return std::nullopt;
    const auto estimate = estimateDecodedBytes(payload, *prototype.GetDescriptor());
    if (!estimate || *estimate <= kHciMaxDecodedBytes)
        return std::nullopt; // malformed bytes are the parser's to name
    return prototype.GetDescriptor()->name() + " of " + std::to_string(payload.size()) + " bytes would decode into more than "
        + std::to_string(kHciMaxDecodedBytes >> 20) + " MiB";
}
} // namespace

const char *toString(HciDropReason reason)
{
    switch (reason) {
    case HciDropReason::BadSignature: return "bad signature";
    case HciDropReason::BadVersion: return "unsupported version";
    case HciDropReason::UnknownType: return "unknown message type";
    case HciDropReason::InvalidPayload: return "invalid protobuf payload";
    case HciDropReason::MissingRequired: return "missing required fields";
    case HciDropReason::BadLength: return "bad length";
    case HciDropReason::TooLarge: return "too large once decoded";
    }
    return "unknown";
}

bool HciFrameHeader::plausible() const
{
    return signature == kHciSignature && version == kHciVersion && length >= 0 && length <= kHciMaxPayload
        && HciMessageTypes::prototype(type) != nullptr;
}

bool appendHciFrame(std::string &out, int32_t instanceId, const google::protobuf::Message &message)
{
    const auto type = HciMessageTypes::number(message.GetDescriptor());
    if (!type || !message.IsInitialized())
        return false;
    const size_t size = message.ByteSizeLong();
    if (size > size_t(kHciMaxPayload))
        return false;
    const size_t start = out.size();
    out.resize(start + kHciHeaderSize + size);
    HciFrameHeader{kHciSignature, kHciVersion, instanceId, *type, int32_t(size)}.write(out.data() + start);
    message.SerializeWithCachedSizesToArray(reinterpret_cast<uint8_t *>(out.data() + start + kHciHeaderSize));
    return true;
}

std::optional<std::string> encodeHciFrame(int32_t instanceId, const google::protobuf::Message &message)
{
    std::string out;
    if (!appendHciFrame(out, instanceId, message))
        return std::nullopt;
    return out;
}

std::string encodeRawHciFrame(int32_t instanceId, int32_t type, std::string_view payload, uint16_t signature,
                              uint16_t version)
{
    std::string out(kHciHeaderSize, '\0');
    HciFrameHeader{signature, version, instanceId, type, int32_t(payload.size())}.write(out.data());
    out.append(payload);
    return out;
}

HciFrameDecoder::HciFrameDecoder() = default;
HciFrameDecoder::~HciFrameDecoder() = default;
HciFrameDecoder::HciFrameDecoder(HciFrameDecoder &&) noexcept = default;
HciFrameDecoder &HciFrameDecoder::operator=(HciFrameDecoder &&) noexcept = default;

void HciFrameDecoder::feed(std::string_view bytes)
{
    // Drop consumed bytes before growing: amortised O(1) per byte, and the buffer never holds
    // more than one partial frame plus the newest chunk.
    if (m_pos > 0 && m_pos >= m_buffer.size() / 2) {
        m_buffer.erase(0, m_pos);
        m_pos = 0;
    }
    m_buffer.append(bytes);
}

void HciFrameDecoder::reset()
{
    m_buffer.clear();
    m_pos = 0;
    m_offset = 0;
    m_resyncing = false;
}

void HciFrameDecoder::recycle(std::unique_ptr<google::protobuf::Message> message)
{
    if (!message)
        return;
    if (m_spares.size() == kSpares)
        m_spares.erase(m_spares.begin());
    m_spares.push_back(std::move(message));
}

std::unique_ptr<google::protobuf::Message> HciFrameDecoder::take(const google::protobuf::Message &prototype)
{
    // typeid, not GetDescriptor(): this runs for every frame, and the descriptor lookup is not free.
    const std::type_info &type = typeid(prototype);
    for (auto it = m_spares.rbegin(); it != m_spares.rend(); ++it) {
        if (typeid(**it) == type) {
            auto message = std::move(*it);
            m_spares.erase(std::next(it).base());
            return message; // the parsers clear it first
        }
    }
    return std::unique_ptr<google::protobuf::Message>(prototype.New());
}

HciDroppedFrame HciFrameDecoder::drop(const HciFrameHeader &header, HciDropReason reason, std::string detail)
{
    ++m_dropped;
    return HciDroppedFrame{m_offset, header, reason, std::move(detail), 0};
}

namespace {
// What next() and decode() share once a frame has been delimited: the header's checks, the decoded
// size, the parse. `newMessage` gives the message to parse into (next() reuses recycled ones).
template<class NewMessage>
HciFrameDecoder::Result decodePayload(uint64_t offset, const HciFrameHeader &header, std::string_view payload,
                                      NewMessage &&newMessage, bool fastPath)
{
    auto dropped = [&](HciDropReason reason, std::string detail) -> HciFrameDecoder::Result {
        return HciDroppedFrame{offset, header, reason, std::move(detail), 0};
    };
    if (header.signature != kHciSignature) {
        char hex[5];
        std::snprintf(hex, sizeof hex, "%04x", header.signature);
        return dropped(HciDropReason::BadSignature, "signature 0x" + std::string(hex));
    }
    if (header.version != kHciVersion)
        return dropped(HciDropReason::BadVersion, "version " + std::to_string(header.version));
    const google::protobuf::Message *prototype = HciMessageTypes::prototype(header.type);
    if (!prototype)
        return dropped(HciDropReason::UnknownType, "type " + std::to_string(header.type) + " is not mapped");
    if (auto tooLarge = decodedSizeProblem(*prototype, payload))
        return dropped(HciDropReason::TooLarge, std::move(*tooLarge));
    std::unique_ptr<google::protobuf::Message> message = newMessage(*prototype);
    if (header.type == kNotificationType && fastPath
        && HciTelemetryFastPath::parse(payload, static_cast<com::ugcs::ucs::proto::Notification *>(message.get()))) {
        // Telemetry, parsed directly: complete by construction, identical to the general parse.
        return HciFrame{offset, header, std::move(message)};
    }
    if (!message->ParsePartialFromArray(payload.data(), int(payload.size())))
        return dropped(HciDropReason::InvalidPayload, std::string(message->GetDescriptor()->name()) + " payload does not parse");
    if (!message->IsInitialized())
        return dropped(HciDropReason::MissingRequired,
                       std::string(message->GetDescriptor()->name()) + " lacks " + message->InitializationErrorString());
    return HciFrame{offset, header, std::move(message)};
}
} // namespace

std::optional<HciRawFrame> HciFrameDecoder::takeWhole(size_t minimumLength)
{
    if (m_resyncing || buffered() < kHciHeaderSize)
        return std::nullopt;
    const char *at = m_buffer.data() + m_pos;
    const HciFrameHeader header = HciFrameHeader::read(at);
    if (header.length < 0 || header.length > kHciMaxPayload || size_t(header.length) < minimumLength
        || buffered() < kHciHeaderSize + size_t(header.length))
        return std::nullopt; // next() handles it: small, incomplete or unusable
    HciRawFrame raw{m_offset, header, std::string(at + kHciHeaderSize, size_t(header.length))};
    m_pos += kHciHeaderSize + size_t(header.length);
    m_offset += kHciHeaderSize + size_t(header.length);
    return raw;
}

HciFrameDecoder::Result HciFrameDecoder::decode(const HciRawFrame &frame)
{
    return decodePayload(frame.offset, frame.header, frame.payload,
                         [](const google::protobuf::Message &prototype) {
                             return std::unique_ptr<google::protobuf::Message>(prototype.New());
                         },
                         true);
}

// Scans for the next offset whose 16 bytes form a plausible header. Consumes everything before it.
// Returns false when more bytes are needed; keeps the last 15 bytes, which may start a header.
bool HciFrameDecoder::resynchronise()
{
    const char *data = m_buffer.data();
    size_t i = m_pos;
    const size_t end = m_buffer.size();
    while (i + kHciHeaderSize <= end) {
        const void *hit = std::memchr(data + i, 0x48, end - i);
        if (!hit) {
            i = end;
            break;
        }
        i = size_t(static_cast<const char *>(hit) - data);
        if (i + kHciHeaderSize > end)
            break;
        if (HciFrameHeader::read(data + i).plausible()) {
            const size_t skipped = i - m_pos;
            m_discarded += skipped;
            m_offset += skipped;
            m_pos = i;
            m_resyncing = false;
            return true;
        }
        ++i;
    }
    const size_t keep = std::min<size_t>(end - m_pos, kHciHeaderSize - 1);
    const size_t skipped = (end - m_pos) - keep;
    m_discarded += skipped;
    m_offset += skipped;
    m_pos += skipped;
    return false;
}

std::optional<HciFrameDecoder::Result> HciFrameDecoder::next()
{
    if (m_resyncing && !resynchronise())
        return std::nullopt;
    if (buffered() < kHciHeaderSize)
        return std::nullopt;

    const char *at = m_buffer.data() + m_pos;
    const HciFrameHeader header = HciFrameHeader::read(at);
    if (header.length < 0 || header.length > kHciMaxPayload) {
        auto dropped = drop(header, HciDropReason::BadLength,
                            "length " + std::to_string(header.length)
                                + " is outside 0..67108864; scanning for the next header");
        // Skip one byte, not the whole header: the next real header may start inside it.
        ++m_pos;
        ++m_offset;
        ++m_discarded;
        dropped.bytesDiscarded = 1;
        m_resyncing = true;
        return dropped;
    }
    const size_t frameSize = kHciHeaderSize + size_t(header.length);
    if (buffered() < frameSize)
        return std::nullopt;

    // The whole frame is here: from now on it is consumed whatever its fate.
    Result result = decodePayload(m_offset, header, std::string_view(at + kHciHeaderSize, size_t(header.length)),
                                  [this](const google::protobuf::Message &prototype) { return take(prototype); },
                                  m_fastPath);
    if (std::holds_alternative<HciFrame>(result))
        ++m_decoded;
    else
        ++m_dropped;
    m_pos += frameSize;
    m_offset += frameSize;
    return result;
}

} // namespace sortie::hci
