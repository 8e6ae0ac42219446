// Fuzzes the HCI frame decoder: any bytes, split at a point the input chooses, must decode without a
// crash, a leak or undefined behaviour, and the decoder must account for every byte it was given.
#include "HciFrameCodec.h"

#include <google/protobuf/message.h>

#include <cstdlib>

using namespace sortie::hci;

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
    return 0;
}
