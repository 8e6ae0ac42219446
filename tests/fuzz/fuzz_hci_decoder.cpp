// Fuzzes the HCI frame decoder: any bytes, split at a point the input chooses, must decode without a
// crash, a leak or undefined behaviour, and the decoder must account for every byte it was given.
// Every frame's payload also goes through both parsers of a Notification: whatever the telemetry fast
// path accepts, the general protobuf parser must accept too, as the same message, byte for byte (the
// fast path may decline anything; then the general parser decides alone). Every payload is also
// measured by estimateDecodedBytes, which the decoder uses on payloads of 1 MiB and more (far past
// -max_len, so it is called directly here): what protobuf parses, the walk must accept, and never
// count far under what the parsed message holds.
#include "HciDecodedSize.h"
#include "HciFrameCodec.h"
#include "HciTelemetryFastPath.h"
#include "Messages.pb.h"

#include <google/protobuf/message.h>

#include <cstdlib>

using namespace sortie::hci;

namespace {

void compareParsers(std::string_view payload)
{
    static com::ugcs::ucs::proto::Notification fast; // reused across inputs, as the decoder reuses it
    com::ugcs::ucs::proto::Notification general;
    const bool generalOk = general.ParsePartialFromArray(payload.data(), int(payload.size())) && general.IsInitialized();
    if (!HciTelemetryFastPath::parse(payload, &fast))
        return;
    if (!generalOk || fast.SerializeAsString() != general.SerializeAsString())
        std::abort();
}

template<class Message>
void checkEstimate(std::string_view payload)
{
    Message parsed;
    if (!parsed.ParsePartialFromArray(payload.data(), int(payload.size())))
        return;
    const auto estimate = estimateDecodedBytes(payload, *Message::descriptor(), SIZE_MAX);
    // Small messages carry fixed costs (a repeated field's first block) the walk leaves out.
    if (!estimate || *estimate * 4 + 4096 < parsed.SpaceUsedLong())
        std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    const size_t split = data[0] % (size);
    const std::string_view bytes(reinterpret_cast<const char *>(data) + 1, size - 1);
    HciFrameDecoder decoder;
    uint64_t consumedEnd = 0;
    auto drain = [&] {
        while (auto r = decoder.next()) {
            if (auto *f = std::get_if<HciFrame>(&*r)) {
                // A decoded frame re-encodes to a frame that decodes to the same message.
                std::string again;
                if (appendHciFrame(again, f->header.instanceId, *f->message)) {
                    HciFrameDecoder second;
                    second.feed(again);
                    auto back = second.next();
                    if (!back || !std::holds_alternative<HciFrame>(*back))
                        std::abort();
                }
                consumedEnd = f->offset + kHciHeaderSize + uint64_t(f->header.length);
            } else {
                consumedEnd = std::get<HciDroppedFrame>(*r).offset;
            }
        }
    };
    decoder.feed(bytes.substr(0, split));
    drain();
    decoder.feed(bytes.substr(split));
    drain();
    if (decoder.streamOffset() + decoder.buffered() != bytes.size() || consumedEnd > bytes.size())
        std::abort();
    // The input as one payload, and every framed payload in it, through both Notification parsers.
    compareParsers(bytes);
    checkEstimate<com::ugcs::ucs::proto::Notification>(bytes);
    checkEstimate<com::ugcs::ucs::proto::GetObjectListResponse>(bytes);
    for (size_t at = 0; at + kHciHeaderSize <= bytes.size(); ++at) {
        if (bytes[at] != 'H' || bytes[at + 1] != 'P')
            continue;
        const auto *h = reinterpret_cast<const uint8_t *>(bytes.data() + at + 12);
        const uint32_t length = uint32_t(h[0]) << 24 | uint32_t(h[1]) << 16 | uint32_t(h[2]) << 8 | h[3];
        if (length <= bytes.size() - at - kHciHeaderSize)
            compareParsers(bytes.substr(at + kHciHeaderSize, length));
    }
    return 0;
}
