#pragma once

#include "VciParser.h"

#include <ostream>
#include <string_view>

namespace sortie::vci {

// Decodes a captured VCI byte stream into JSON lines (vciDumpLine), one per message and one per error,
// for sortie-dump. Feed chunks of any size, then finish(): bytes left over that never became a message
// are reported as a last error line ("truncated"). Pure: writes to a std::ostream.
class VciDumpWriter
{
public:
    explicit VciDumpWriter(std::ostream &out, VciLimits limits = {}) : m_out(out), m_parser(limits) {}

    void feed(std::string_view bytes);
    void finish();

    uint64_t messages() const { return m_parser.messagesParsed(); }
    uint64_t errors() const { return m_parser.errors() + m_truncated; }

private:
    void drain();

    std::ostream &m_out;
    VciParser m_parser;
    uint64_t m_truncated = 0;
};

} // namespace sortie::vci
