#pragma once

#include <cstdint>
#include <string>

namespace sortie::vci {

// Decodes the inside of one JSON string incrementally (after its opening quote): escapes, \u
// surrogate pairs, and a check that the raw bytes are valid UTF-8 (no overlong forms, no surrogates,
// nothing above U+10FFFF) and hold no control characters. Used by VciJsonReader for keys and values.
class VciJsonString
{
public:
    enum class Status { Open, Closed, Error };

    void reset()
    {
        m_escape = Escape::None;
        m_high = 0;
        m_utf8Need = 0;
    }

    // Appends decoded text to `out` until the closing quote (consumed), an error (the bad byte is not
    // consumed) or `end`. Returns where it stopped.
    const char *decode(const char *p, const char *end, std::string &out, Status *status);
    const std::string &error() const { return m_error; }

private:
    enum class Escape : uint8_t { None, Backslash, Hex, NeedLowBackslash, NeedLowU, LowHex };

    bool escape(char c, std::string &out);
    bool fail(std::string message);
    static void appendUtf8(uint32_t cp, std::string &out);

    Escape m_escape = Escape::None;
    uint8_t m_hexDigits = 0;
    uint32_t m_hex = 0, m_high = 0;
    uint8_t m_utf8Need = 0; // continuation bytes still due in a multi-byte character
    uint8_t m_utf8Lo = 0x80, m_utf8Hi = 0xBF;
    std::string m_error;
};

} // namespace sortie::vci
