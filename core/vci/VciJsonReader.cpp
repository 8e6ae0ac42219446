#include "VciJsonReader.h"

#include <charconv>
#include <cstdio>

namespace sortie::vci {
namespace {

using nlohmann::json;

inline bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
inline bool isDigit(char c) { return c >= '0' && c <= '9'; }

std::string describe(char c)
{
    const auto u = static_cast<unsigned char>(c);
    char buf[16];
    if (u >= 0x20 && u < 0x7f)
        std::snprintf(buf, sizeof buf, "'%c'", c);
    else
        std::snprintf(buf, sizeof buf, "byte 0x%02X", u);
    return buf;
}

// Number grammar states: which characters may follow, and where the number may end.
constexpr uint8_t NStart = 0, NMinus = 1, NZero = 2, NInt = 3, NDot = 4, NFrac = 5, NExp = 6, NExpSign = 7, NExpDigits = 8;
inline bool numberMayEnd(uint8_t s) { return s == NZero || s == NInt || s == NFrac || s == NExpDigits; }

constexpr uint8_t kEnd = 254, kBad = 255;

inline uint8_t numberStep(uint8_t s, char c)
{
    switch (s) {
    case NStart: return c == '-' ? NMinus : c == '0' ? NZero : isDigit(c) ? NInt : kBad;
    case NMinus: return c == '0' ? NZero : isDigit(c) ? NInt : kBad;
    case NZero: return c == '.' ? NDot : (c == 'e' || c == 'E') ? NExp : isDigit(c) ? kBad : kEnd;
    case NInt: return isDigit(c) ? NInt : c == '.' ? NDot : (c == 'e' || c == 'E') ? NExp : kEnd;
    case NDot: return isDigit(c) ? NFrac : kBad;
    case NFrac: return isDigit(c) ? NFrac : (c == 'e' || c == 'E') ? NExp : kEnd;
    case NExp: return (c == '+' || c == '-') ? NExpSign : isDigit(c) ? NExpDigits : kBad;
    case NExpSign: return isDigit(c) ? NExpDigits : kBad;
    case NExpDigits: return isDigit(c) ? NExpDigits : kEnd;
    }
    return kBad;
}

} // namespace

VciJsonReader::VciJsonReader(size_t maxDepth, size_t maxBytes, size_t maxNumberLength, size_t maxDecodedBytes)
    : m_maxDepth(maxDepth), m_maxBytes(maxBytes), m_maxNumber(maxNumberLength), m_maxDecoded(maxDecodedBytes)
{
    m_text.reserve(64);
    m_key.reserve(32);
    m_stack.reserve(16);
}

void VciJsonReader::reset()
{
    m_status = Status::NeedMore;
    m_state = State::Value;
    m_closeAllowed = false;
    m_stringIsKey = false;
    m_string.reset();
    m_consumed = 0;
    m_decodedBytes = 0;
    m_errorOffset = 0;
    m_error.clear();
    m_text.clear();
    m_key.clear();
    m_stack.clear();
    m_root = nullptr;
}

nlohmann::json VciJsonReader::takeValue()
{
    json v = std::move(m_root);
    m_root = nullptr;
    return v;
}

bool VciJsonReader::fail(const char *at, std::string message)
{
    m_errorOffset = at ? m_feedBase + uint64_t(at - m_feedData) : m_consumed;
    m_error = "invalid JSON at body byte " + std::to_string(m_errorOffset) + ": " + std::move(message);
    m_status = Status::Error;
    m_state = State::Error;
    return false;
}

bool VciJsonReader::unexpected(const char *at, const char *expected)
{
    return fail(at, std::string("expected ") + expected + ", found " + describe(*at));
}

namespace {
// What the allocator adds to each block (glibc: 16 bytes of header and rounding, near enough).
constexpr size_t kBlockOverhead = 16;
size_t heapString(size_t length)
{
    return length < 16 ? 0 : length + 1 + kBlockOverhead; // short strings live inside the object
}
} // namespace

bool VciJsonReader::account(const json &v, bool inObject)
{
    // The node itself: in an array a slot of the vector, which holds up to twice the slots it
    // uses while it grows; in an object a map node (tree links and colour) with its key.
    size_t cost = inObject ? sizeof(json::object_t::value_type) + 32 + kBlockOverhead + heapString(m_key.size())
                           : 2 * sizeof(json);
    if (v.is_string())
        cost += sizeof(json::string_t) + kBlockOverhead + heapString(v.get_ref<const json::string_t &>().size());
    else if (v.is_array())
        cost += sizeof(json::array_t) + kBlockOverhead;
    else if (v.is_object())
        cost += sizeof(json::object_t) + kBlockOverhead;
    m_decodedBytes += cost;
    return m_decodedBytes <= m_maxDecoded;
}

json *VciJsonReader::place(json &&v)
{
    if (!account(v, !m_stack.empty() && m_stack.back()->is_object())) {
        // Past the bound: free what was built now, not when the next message resets the reader.
        m_stack.clear();
        m_root = nullptr;
        m_errorOffset = m_consumed;
        m_error = "body would take more than " + std::to_string(m_maxDecoded >> 20) + " MiB of memory once read";
        m_status = Status::Error;
        m_state = State::Error;
        return nullptr;
    }
    if (m_stack.empty()) {
        m_root = std::move(v);
        return &m_root;
    }
    json *top = m_stack.back();
    if (top->is_array()) {
        auto &array = top->get_ref<json::array_t &>();
        array.push_back(std::move(v));
        return &array.back();
    }
    auto &object = top->get_ref<json::object_t &>();
    return &object.insert_or_assign(std::move(m_key), std::move(v)).first->second;
}

bool VciJsonReader::store(json &&v)
{
    if (!place(std::move(v)))
        return false;
    valueDone();
    return true;
}

void VciJsonReader::valueDone()
{
    if (m_stack.empty()) {
        m_state = State::Done;
        m_status = Status::Done;
    } else {
        m_state = State::AfterValue;
    }
}

bool VciJsonReader::openContainer(const char *at, bool object)
{
    if (m_stack.size() >= m_maxDepth)
        return fail(at, "nested deeper than " + std::to_string(m_maxDepth) + " arrays and objects");
    json *container = place(object ? json::object() : json::array());
    if (!container)
        return false;
    m_stack.push_back(container);
    m_closeAllowed = true;
    m_state = object ? State::Key : State::Value;
    return true;
}

bool VciJsonReader::closeContainer(const char *at)
{
    const bool object = m_stack.back()->is_object();
    if ((*at == '}') != object)
        return unexpected(at, object ? "',' or '}'" : "',' or ']'");
    m_stack.pop_back();
    valueDone();
    return true;
}

const char *VciJsonReader::readString(const char *p, const char *end)
{
    VciJsonString::Status status;
    p = m_string.decode(p, end, m_stringIsKey ? m_key : m_text, &status);
    if (status == VciJsonString::Status::Error) {
        fail(p, m_string.error());
    } else if (status == VciJsonString::Status::Closed) {
        if (m_stringIsKey) {
            m_state = State::Colon;
        } else {
            store(json(std::move(m_text)));
            m_text.clear();
        }
    }
    return p;
}

const char *VciJsonReader::readNumber(const char *p, const char *end)
{
    const char *run = p; // characters accepted but not yet copied into m_text
    auto flush = [&] {
        m_text.append(run, size_t(p - run));
        run = p;
    };
    while (p < end) {
        if ((m_numState == NInt || m_numState == NFrac || m_numState == NExpDigits) && isDigit(*p)
            && m_text.size() + size_t(p - run) < m_maxNumber) {
            ++p; // the common case: more digits in a state that takes them
            continue;
        }
        const uint8_t next = numberStep(m_numState, *p);
        if (next < kEnd && m_text.size() + size_t(p - run) < m_maxNumber) {
            m_numState = next;
            ++p;
            continue;
        }
        flush();
        if (next == kEnd) {
            const bool topLevel = m_stack.empty();
            if (topLevel && !isSpace(*p))
                return unexpected(p, "a whitespace character after a top-level number"), p;
            if (!completeNumber(p))
                return p;
            return topLevel ? p + 1 : p; // the whitespace that ends a top-level number is the body's
        }
        if (next == kBad)
            return unexpected(p, m_numState == NDot ? "a digit after '.'" : "a digit"), p;
        return fail(p, "a number longer than " + std::to_string(m_maxNumber) + " characters"), p;
    }
    flush();
    return p;
}

bool VciJsonReader::completeNumber(const char *at)
{
    const char *b = m_text.data();
    const char *e = b + m_text.size();
    if (m_numState == NZero || m_numState == NInt) {
        if (*b == '-') {
            int64_t v = 0;
            const auto r = std::from_chars(b, e, v);
            if (r.ec == std::errc() && r.ptr == e) {
                return store(json(v));
            }
        } else {
            uint64_t v = 0;
            const auto r = std::from_chars(b, e, v);
            if (r.ec == std::errc() && r.ptr == e) {
                return store(json(v));
            }
        }
    }
    double d = 0;
    const auto r = std::from_chars(b, e, d);
    if (r.ec == std::errc::result_out_of_range) {
        // Underflow reads as zero; overflow has no JSON value to become.
        const bool tiny = m_text.find("e-") != std::string::npos || m_text.find("E-") != std::string::npos;
        if (!tiny)
            return fail(at, "number " + m_text + " is out of range");
        d = *b == '-' ? -0.0 : 0.0;
    } else if (r.ec != std::errc() || r.ptr != e) {
        return fail(at, "number " + m_text + " cannot be read");
    }
    return store(json(d));
}

size_t VciJsonReader::feed(const char *data, size_t size)
{
    if (m_status != Status::NeedMore)
        return 0;
    const size_t room = m_maxBytes - m_consumed;
    const bool capped = size > room;
    if (capped)
        size = room;
    m_feedData = data;
    m_feedBase = m_consumed;
    const char *p = data;
    const char *end = data + size;
    while (p < end && m_status == Status::NeedMore) {
        switch (m_state) {
        case State::Value: {
            const char c = *p;
            if (isSpace(c)) {
                ++p;
            } else if (c == '{' || c == '[') {
                if (openContainer(p, c == '{'))
                    ++p;
            } else if (c == ']' && m_closeAllowed) {
                if (closeContainer(p))
                    ++p;
            } else if (c == '"') {
                ++p;
                m_state = State::String;
                m_stringIsKey = false;
                m_string.reset();
                m_text.clear();
            } else if (c == '-' || isDigit(c)) {
                m_state = State::Number;
                m_numState = NStart;
                m_text.clear();
            } else if (c == 't' || c == 'f' || c == 'n') {
                m_literal = c == 't' ? "true" : c == 'f' ? "false" : "null";
                m_literalPos = 0;
                m_state = State::Literal;
            } else {
                unexpected(p, "a JSON value");
            }
            break;
        }
        case State::String:
            p = readString(p, end);
            break;
        case State::Number:
            p = readNumber(p, end);
            break;
        case State::Literal:
            if (*p != m_literal[m_literalPos]) {
                unexpected(p, (std::string("'") + m_literal[m_literalPos] + "' of " + m_literal).c_str());
                break;
            }
            ++p;
            if (m_literal[++m_literalPos] == 0) {
                store(m_literal[0] == 'n' ? json(nullptr) : json(m_literal[0] == 't'));
            }
            break;
        case State::AfterValue: {
            const char c = *p;
            if (isSpace(c)) {
                ++p;
            } else if (c == ',') {
                ++p;
                m_closeAllowed = false;
                m_state = m_stack.back()->is_object() ? State::Key : State::Value;
            } else if (c == '}' || c == ']') {
                if (closeContainer(p))
                    ++p;
            } else {
                unexpected(p, m_stack.back()->is_object() ? "',' or '}'" : "',' or ']'");
            }
            break;
        }
        case State::Key: {
            const char c = *p;
            if (isSpace(c)) {
                ++p;
            } else if (c == '"') {
                ++p;
                m_state = State::String;
                m_stringIsKey = true;
                m_string.reset();
                m_key.clear();
            } else if (c == '}' && m_closeAllowed) {
                if (closeContainer(p))
                    ++p;
            } else {
                unexpected(p, m_closeAllowed ? "a key or '}'" : "a key");
            }
            break;
        }
        case State::Colon:
            if (isSpace(*p)) {
                ++p;
            } else if (*p == ':') {
                ++p;
                m_closeAllowed = false;
                m_state = State::Value;
            } else {
                unexpected(p, "':'");
            }
            break;
        case State::Done:
        case State::Error:
            break;
        }
    }
    const size_t n = size_t(p - data);
    m_consumed += n;
    if (capped && m_status == Status::NeedMore) {
        m_errorOffset = m_consumed;
        m_error = "body larger than the limit of " + std::to_string(m_maxBytes) + " bytes";
        m_status = Status::Error;
        m_state = State::Error;
    }
    return n;
}

VciJsonReader::Status VciJsonReader::finish()
{
    if (m_status != Status::NeedMore)
        return m_status;
    m_feedData = nullptr;
    if (m_state == State::Number && m_stack.empty() && numberMayEnd(m_numState)) {
        completeNumber(nullptr);
        return m_status;
    }
    if (m_state == State::Value && m_stack.empty())
        fail(nullptr, "the body holds no JSON value");
    else
        fail(nullptr, "the body ends inside a JSON value");
    return m_status;
}

} // namespace sortie::vci
