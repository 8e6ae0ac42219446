#pragma once

#include "VciJsonString.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sortie::vci {

// Incremental JSON reader: finds where one JSON value ends and builds it in the same pass, from
// chunks of any size. It stops at the value's last byte, so what follows stays with the caller; a
// top-level number has no last byte of its own and ends at one whitespace character, which it
// consumes (the VCI rule). Strings are checked for valid UTF-8 and escapes; numbers follow the JSON
// grammar (non-negative integers become unsigned, negative ones signed, others double, as
// nlohmann::json::parse does). Pure: no I/O, no Qt.
class VciJsonReader
{
public:
    enum class Status { NeedMore, Done, Error };

    // maxDecodedBytes bounds what the value takes in memory, not only on the wire: `[[],[],…]` is
    // three bytes an element on the wire and over seventy in a DOM, so a 16 MiB body of it would
    // hold hundreds of MiB. The reader counts what each value it builds allocates (the json node,
    // its array slot with the vector's spare capacity or its map node and key, a string's buffer, a
    // container's own object) and stops with an error, freeing what it built, once past the bound.
    explicit VciJsonReader(size_t maxDepth = 256, size_t maxBytes = 16 * 1024 * 1024, size_t maxNumberLength = 512,
                           size_t maxDecodedBytes = 192 * 1024 * 1024);

    // Reads from `data` until the value is complete, an error is found or the bytes run out.
    // Returns the bytes consumed; the byte that caused an error is not consumed.
    size_t feed(const char *data, size_t size);
    // The input has ended (a Content-Length body is complete): ends a pending top-level number.
    Status finish();

    Status status() const { return m_status; }
    const std::string &error() const { return m_error; }
    uint64_t consumed() const { return m_consumed; } // bytes of the value read so far
    // What the value built so far takes in memory, as counted against maxDecodedBytes.
    size_t decodedBytes() const { return m_decodedBytes; }
    uint64_t errorOffset() const { return m_errorOffset; } // body byte where the error was found
    nlohmann::json &value() { return m_root; }
    nlohmann::json takeValue();
    void reset();

private:
    enum class State : uint8_t { Value, String, Number, Literal, AfterValue, Key, Colon, Done, Error };

    const char *readString(const char *p, const char *end);
    const char *readNumber(const char *p, const char *end);
    bool completeNumber(const char *at);
    bool openContainer(const char *at, bool object);
    bool closeContainer(const char *at);
    nlohmann::json *place(nlohmann::json &&v); // nullptr once past maxDecodedBytes
    bool store(nlohmann::json &&v);             // places a scalar or string and ends it
    bool account(const nlohmann::json &v, bool inObject); // false once past maxDecodedBytes
    void valueDone();
    bool fail(const char *at, std::string message); // at == nullptr: at the end of the input
    bool unexpected(const char *at, const char *expected);

    size_t m_maxDepth, m_maxBytes, m_maxNumber, m_maxDecoded;
    size_t m_decodedBytes = 0;
    Status m_status = Status::NeedMore;
    State m_state = State::Value;
    bool m_closeAllowed = false;   // ']' or '}' may close the container (right after it opened)
    bool m_stringIsKey = false;
    VciJsonString m_string;        // the string being read
    uint8_t m_numState = 0;
    const char *m_literal = nullptr;
    uint8_t m_literalPos = 0;
    uint64_t m_consumed = 0;
    uint64_t m_errorOffset = 0;
    const char *m_feedData = nullptr; // the chunk being read, to place errors
    uint64_t m_feedBase = 0;
    std::string m_error;
    std::string m_text;            // the string or number being read
    std::string m_key;             // the key waiting for its value
    std::vector<nlohmann::json *> m_stack; // open containers, innermost last
    nlohmann::json m_root;
};

} // namespace sortie::vci
