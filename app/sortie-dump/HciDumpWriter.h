#pragma once

#include "HciFrameCodec.h"

#include <cstdint>
#include <ostream>
#include <string_view>

namespace sortie::dump {

// Turns a captured HCI byte stream into JSON lines, one per frame:
//   {"offset":0,"instanceId":0,"type":20,"message":"AuthorizeHciRequest","json":{...}}
// where json is the message as protobuf JSON (lowerCamelCase names, int64 as strings). A frame the
// decoder drops is a line with "dropped" (the reason) and "detail"; bytes left at the end of the stream
// that never made a whole frame are one "truncated" line. Passwords (userPassword, password) are shown
// as "***" unless secrets are revealed. Pure: no Qt objects, no I/O besides the given stream.
class HciDumpWriter
{
public:
    struct Options
    {
        bool revealSecrets = false;
    };

    explicit HciDumpWriter(std::ostream &out);
    HciDumpWriter(std::ostream &out, Options options);

    void feed(std::string_view bytes);
    // Call at the end of the stream: reports an incomplete frame, if any.
    void finish();

    uint64_t framesDecoded() const { return m_decoder.framesDecoded(); }
    uint64_t framesDropped() const { return m_decoder.framesDropped() + m_truncated; }

private:
    void drain();
    void writeFrame(hci::HciFrame &frame);
    void writeDropped(const hci::HciDroppedFrame &dropped);

    std::ostream &m_out;
    Options m_options;
    hci::HciFrameDecoder m_decoder;
    uint64_t m_truncated = 0;
};

} // namespace sortie::dump
