#pragma once

#include "VciHeaders.h"
#include "VciTypes.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace sortie::vci {

// One VCI message as read from the stream or about to be written: a request (verb and URI) or a
// response (status and reason), its headers and its body. JSON bodies are parsed into `body`; a body
// of another content type is kept as bytes in `rawBody`.
struct VciMessage
{
    uint64_t offset = 0;  // stream offset of the start line's first byte
    uint64_t size = 0;    // bytes on the wire, start line to the end of the body
    VciMessageKind kind = VciMessageKind::Request;
    VciVerb verb = VciVerb::Get;  // requests
    std::string uri;              // requests: "/path" or "*"
    int status = 0;               // responses
    std::string reason;           // responses
    VciHeaders headers;
    bool hasBody = false;
    bool jsonBody = false;        // true when `body` holds the parsed value
    nlohmann::json body;          // null unless jsonBody
    std::string rawBody;          // a non-JSON body, framed by Content-Length

    bool isRequest() const { return kind == VciMessageKind::Request; }
    bool isResponse() const { return kind == VciMessageKind::Response; }
};

// Why a message could not be read. Each names what an operator or the peer's developer has to fix.
enum class VciErrorCode : uint8_t {
    BadStartLine,       // neither "VERB /uri VCI/1.0" nor "VCI/1.0 200 OK"
    UnsupportedVersion, // a protocol other than VCI/1.0
    UnknownVerb,        // a well-formed request line with a verb VCI/1.0 does not define (answered 501)
    BadUri,             // a URI that is not "/..." (or "*" for UNSUBSCRIBE)
    BadHeader,          // a header line without "name:" or with control characters
    LineTooLong,        // a start or header line over VciLimits::maxLineLength
    TooManyHeaders,     // more than VciLimits::maxHeaders header lines
    MissingEmptyLine,   // a new start line arrived before the empty line that ends the headers
    BadContentLength,   // Content-Length is not a number, or two of them disagree
    BodyTooLarge,       // a body over VciLimits::maxBodySize
    BadJson,            // the body of a JSON message is not valid JSON
};

std::string_view toString(VciErrorCode code);

// A message that was dropped, with where it started and why. The parser has already skipped it:
// either exactly its bytes (when its framing could be trusted) or up to the next line that starts a
// message (after a body whose end cannot be known); `bytesDiscarded` counts the latter.
struct VciParseError
{
    uint64_t offset = 0;
    VciErrorCode code = VciErrorCode::BadStartLine;
    std::string message;
    bool kindKnown = false;       // the start line told a request from a response
    VciMessageKind kind = VciMessageKind::Request;
    std::string verb;             // as sent, even when unknown
    std::string uri;

    // The status the peer gets for this message: 501 for an unknown verb, 400 for any other bad
    // request, 0 for a response or a NOTIFY (neither is ever answered).
    int replyStatus() const;
};

} // namespace sortie::vci
