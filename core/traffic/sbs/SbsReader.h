#pragma once

#include "SbsMessage.h"

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace sortie::traffic::sbs {

// Reads an SBS-1 byte stream: push bytes as they arrive, pull what they made. A line ends at '\n'
// (a '\r' before it is dropped). Every line is checked before any of it is believed; one that is
// not a well-formed MSG line is dropped with its line number and reason, and reading goes on with
// the next line. A line longer than the limit is dropped as soon as it passes it, and the reader
// waits for the next newline to start again, so a stream without newlines never holds more than
// the limit. Valid lines of the other BaseStation kinds (SEL, ID, AIR, STA, CLK) and empty lines
// are skipped and counted, not reported as errors.
class SbsReader
{
public:
    using Result = std::variant<SbsMessage, SbsError>;
    static constexpr size_t kDefaultMaxLineLength = 512; // a real line is under 200 bytes

    explicit SbsReader(size_t maxLineLength = kDefaultMaxLineLength);

    void push(std::string_view bytes);
    // The next message or dropped line, in stream order; nothing when all that was pushed is read.
    std::optional<Result> next();

    uint64_t linesSeen() const { return m_line; }
    uint64_t skippedLines() const { return m_skipped; }
    size_t buffered() const { return m_partial.size(); }

    // Reads one line without its newline (exposed for tests and the fuzzer).
    static std::optional<Result> readLine(std::string_view line, uint64_t lineNumber, bool *skipped = nullptr);

private:
    void finishLine();

    size_t m_maxLineLength;
    std::string m_partial;
    bool m_discarding = false; // inside a line that was too long, until its newline
    uint64_t m_line = 0;
    uint64_t m_skipped = 0;
    std::deque<Result> m_ready;
};

} // namespace sortie::traffic::sbs
