#pragma once

#include "VciJsonReader.h"
#include "VciMessage.h"

#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace sortie::vci {

// Incremental VCI reader: one parser reads requests and responses from the same stream, fed in chunks
// of any size, and hands out each message once, in stream order, or the error that dropped it.
//
// Framing: a start line, header lines, an empty line (lines end with CRLF; a bare LF is accepted), then
// a body of Content-Length bytes, or, with a JSON Content-Type and no Content-Length, exactly one JSON
// value whose end the JSON itself tells (a top-level number ends at one whitespace character). JSON
// bodies are parsed while their end is looked for, never twice.
//
// Recovery: a message whose start line or headers are bad is still framed by its headers, so exactly its
// bytes are skipped. When the body's end cannot be known (invalid JSON without Content-Length, a bad or
// oversized Content-Length) the parser skips to the next line that is a valid start line. Memory is
// bounded by VciLimits: a line, a header count and a body over the limits is reported, never buffered.
// Pure: no I/O, no Qt objects.
class VciParser
{
public:
    using Result = std::variant<VciMessage, VciParseError>;

    explicit VciParser(VciLimits limits = {});

    void feed(std::string_view bytes);
    // The next message or error, or nullopt when more bytes are needed.
    std::optional<Result> next();

    const VciLimits &limits() const { return m_limits; }
    size_t buffered() const { return m_buf.size() - m_pos; }
    uint64_t streamOffset() const { return m_offset + m_pos; } // of the next unread byte
    uint64_t messagesParsed() const { return m_messages; }
    uint64_t errors() const { return m_errors; }
    uint64_t bytesDiscarded() const { return m_discarded; } // skipped while looking for a start line
    // Whether a message has begun and not ended (its start line is read), and where it began.
    bool midMessage() const { return m_state == State::Headers || m_state == State::BodyLength || m_state == State::BodyJson; }
    uint64_t messageOffset() const { return midMessage() ? m_msg.offset : streamOffset(); }
    bool resyncing() const { return m_state == State::Resync; } // skipping to the next start line
    void reset();

private:
    enum class State : uint8_t { StartLine, Headers, BodyLength, BodyJson, Resync };
    enum class Line : uint8_t { Ready, NeedMore, TooLong };
    enum class Step : uint8_t { NeedMore, Continue, Produced };

    Line takeLine(std::string_view *line, size_t *lineStart);
    Step onStartLine();
    Step onHeaderLine();
    Step endOfHeaders();
    Step onBodyLength();
    Step onBodyJson();
    Step onResync();
    void beginMessage(uint64_t offset);
    void setError(VciErrorCode code, std::string message);
    void setReaderError(); // the JSON reader stopped: a bad value, or one too large once read
    Step produce();                 // the current message (or its error) is complete
    Step produceAndResync();        // its end cannot be known: report it, then look for a start line
    VciParseError makeError() const;
    bool skipLongLineRest(bool countDiscarded);

    VciLimits m_limits;
    std::string m_buf;
    size_t m_pos = 0;          // first unread byte in m_buf
    uint64_t m_offset = 0;     // stream offset of m_buf[0]
    State m_state = State::StartLine;
    bool m_skipLine = false;   // discarding the rest of an over-long line

    VciMessage m_msg;
    bool m_bad = false;
    bool m_msgKindKnown = false;
    VciErrorCode m_errCode = VciErrorCode::BadStartLine;
    std::string m_errMessage;
    std::string m_verbText;    // as sent, for errors about unknown verbs
    size_t m_headerLines = 0;
    std::optional<uint64_t> m_contentLength;
    bool m_lengthBad = false;
    bool m_json = false;
    uint64_t m_remaining = 0;
    VciJsonReader m_reader;

    std::optional<Result> m_result;
    uint64_t m_messages = 0, m_errors = 0, m_discarded = 0;
};

} // namespace sortie::vci
