#include "VciJsonString.h"

#include <cstdio>

namespace sortie::vci {
namespace {

int hexValue(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

} // namespace

bool VciJsonString::fail(std::string message)
{
    m_error = std::move(message);
    return false;
}

void VciJsonString::appendUtf8(uint32_t cp, std::string &out)
{
    if (cp < 0x80) {
        out.push_back(char(cp));
    } else if (cp < 0x800) {
        out.push_back(char(0xC0 | (cp >> 6)));
        out.push_back(char(0x80 | (cp & 0x3F)));
    } else if (cp < 0x10000) {
        out.push_back(char(0xE0 | (cp >> 12)));
        out.push_back(char(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(char(0x80 | (cp & 0x3F)));
    } else {
        out.push_back(char(0xF0 | (cp >> 18)));
        out.push_back(char(0x80 | ((cp >> 12) & 0x3F)));
        out.push_back(char(0x80 | ((cp >> 6) & 0x3F)));
        out.push_back(char(0x80 | (cp & 0x3F)));
    }
}

bool VciJsonString::escape(char c, std::string &out)
{
    switch (m_escape) {
    case Escape::Backslash:
        switch (c) {
        case '"': out.push_back('"'); break;
        case '\\': out.push_back('\\'); break;
        case '/': out.push_back('/'); break;
        case 'b': out.push_back('\b'); break;
        case 'f': out.push_back('\f'); break;
        case 'n': out.push_back('\n'); break;
        case 'r': out.push_back('\r'); break;
        case 't': out.push_back('\t'); break;
        case 'u':
            m_escape = Escape::Hex;
            m_hexDigits = 0;
            m_hex = 0;
            return true;
        default:
            return fail(std::string("invalid escape \\") + (c >= 0x20 && c < 0x7f ? c : '?') + " in a string");
        }
        m_escape = Escape::None;
        return true;
    case Escape::Hex:
    case Escape::LowHex: {
        const int d = hexValue(c);
        if (d < 0)
            return fail("expected a hexadecimal digit in a \\u escape");
        m_hex = m_hex * 16 + uint32_t(d);
        if (++m_hexDigits < 4)
            return true;
        if (m_escape == Escape::LowHex) {
            if (m_hex < 0xDC00 || m_hex > 0xDFFF)
                return fail("a \\u high surrogate must be followed by a low surrogate");
            appendUtf8(0x10000 + ((m_high - 0xD800) << 10) + (m_hex - 0xDC00), out);
            m_high = 0;
            m_escape = Escape::None;
        } else if (m_hex >= 0xD800 && m_hex <= 0xDBFF) {
            m_high = m_hex;
            m_escape = Escape::NeedLowBackslash;
        } else if (m_hex >= 0xDC00 && m_hex <= 0xDFFF) {
            return fail("a \\u low surrogate without a high surrogate before it");
        } else {
            appendUtf8(m_hex, out);
            m_escape = Escape::None;
        }
        return true;
    }
    case Escape::NeedLowBackslash:
    case Escape::NeedLowU:
        if (c != (m_escape == Escape::NeedLowBackslash ? '\\' : 'u'))
            return fail("a \\u high surrogate must be followed by a low surrogate");
        if (m_escape == Escape::NeedLowBackslash) {
            m_escape = Escape::NeedLowU;
        } else {
            m_escape = Escape::LowHex;
            m_hexDigits = 0;
            m_hex = 0;
        }
        return true;
    case Escape::None:
        break;
    }
    return true;
}

const char *VciJsonString::decode(const char *p, const char *end, std::string &out, Status *status)
{
    *status = Status::Open;
    while (p < end) {
        if (m_escape != Escape::None) {
            if (!escape(*p, out)) {
                *status = Status::Error;
                return p;
            }
            ++p;
            continue;
        }
        if (m_utf8Need) {
            const auto u = static_cast<unsigned char>(*p);
            if (u < m_utf8Lo || u > m_utf8Hi) {
                fail("invalid UTF-8 in a string");
                *status = Status::Error;
                return p;
            }
            out.push_back(*p++);
            --m_utf8Need;
            m_utf8Lo = 0x80;
            m_utf8Hi = 0xBF;
            continue;
        }
        // The common case: a run of printable ASCII, appended at once.
        const char *run = p;
        while (p < end) {
            const auto u = static_cast<unsigned char>(*p);
            if (u < 0x20 || u == '"' || u == '\\' || u >= 0x80)
                break;
            ++p;
        }
        out.append(run, size_t(p - run));
        if (p == end)
            break;
        const auto u = static_cast<unsigned char>(*p);
        if (u == '"') {
            *status = Status::Closed;
            return p + 1;
        }
        if (u == '\\') {
            m_escape = Escape::Backslash;
            ++p;
            continue;
        }
        if (u < 0x20) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "control character 0x%02X in a string (escape it)", u);
            fail(buf);
            *status = Status::Error;
            return p;
        }
        if (u >= 0xC2 && u <= 0xDF) {
            m_utf8Need = 1;
        } else if (u >= 0xE0 && u <= 0xEF) {
            m_utf8Need = 2;
            m_utf8Lo = u == 0xE0 ? 0xA0 : 0x80; // no overlong forms
            m_utf8Hi = u == 0xED ? 0x9F : 0xBF; // no surrogates
        } else if (u >= 0xF0 && u <= 0xF4) {
            m_utf8Need = 3;
            m_utf8Lo = u == 0xF0 ? 0x90 : 0x80;
            m_utf8Hi = u == 0xF4 ? 0x8F : 0xBF; // nothing above U+10FFFF
        } else {
            fail("invalid UTF-8 in a string");
            *status = Status::Error;
            return p;
        }
        out.push_back(*p++);
    }
    return p;
}

} // namespace sortie::vci
