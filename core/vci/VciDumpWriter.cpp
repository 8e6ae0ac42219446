#include "VciDumpWriter.h"

#include "VciDump.h"

namespace sortie::vci {

void VciDumpWriter::feed(std::string_view bytes)
{
    m_parser.feed(bytes);
    drain();
}

void VciDumpWriter::drain()
{
    while (auto result = m_parser.next())
        m_out << vciDumpLine(*result).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
}

void VciDumpWriter::finish()
{
    drain();
    // Whatever is left is a message cut short (a partial line, headers without their end, a body).
    if (!m_parser.midMessage() && (m_parser.buffered() == 0 || m_parser.resyncing()))
        return;
    ++m_truncated;
    const nlohmann::json line = {{"offset", m_parser.messageOffset()},
                                 {"kind", "error"},
                                 {"error", "truncated"},
                                 {"message", "the capture ends inside a message"}};
    m_out << line.dump() << '\n';
}

} // namespace sortie::vci
