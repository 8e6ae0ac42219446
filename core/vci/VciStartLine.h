#pragma once

#include "VciMessage.h"

#include <string>
#include <string_view>

namespace sortie::vci {

// The first line of a message, split and checked: "VERB /uri VCI/1.0" or "VCI/1.0 200 OK".
// Views point into the line given to parseVciStartLine().
struct VciStartLine
{
    bool ok = false;
    VciErrorCode error = VciErrorCode::BadStartLine; // when !ok
    std::string message;                             // when !ok
    bool kindKnown = false;
    VciMessageKind kind = VciMessageKind::Request;
    VciVerb verb = VciVerb::Get;
    std::string_view verbText;
    std::string_view uri;
    int status = 0;
    std::string_view reason;
};

// `line` without its line ending.
VciStartLine parseVciStartLine(std::string_view line);

// RFC 7230 token: what a verb or a header name is made of.
bool isVciToken(std::string_view s);

} // namespace sortie::vci
