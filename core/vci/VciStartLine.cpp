#include "VciStartLine.h"

namespace sortie::vci {
namespace {

// RFC 7230 token characters: what a verb or a header name may be made of.
bool isTokenChar(char c)
{
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))
        return true;
    switch (c) {
    case '!': case '#': case '$': case '%': case '&': case '\'': case '*': case '+':
    case '-': case '.': case '^': case '_': case '`': case '|': case '~':
        return true;
    default:
        return false;
    }
}

} // namespace

bool isVciToken(std::string_view s)
{
    if (s.empty())
        return false;
    for (char c : s) {
        if (!isTokenChar(c))
            return false;
    }
    return true;
}

namespace {

std::string quoted(std::string_view s)
{
    constexpr size_t kShown = 60;
    std::string out = "\"";
    for (char c : s.substr(0, kShown)) {
        const auto u = static_cast<unsigned char>(c);
        out += (u >= 0x20 && u < 0x7f) ? c : '?';
    }
    out += s.size() > kShown ? "...\"" : "\"";
    return out;
}

VciStartLine bad(VciStartLine r, VciErrorCode code, std::string message)
{
    r.ok = false;
    r.error = code;
    r.message = std::move(message);
    return r;
}

VciStartLine parseStatusLine(std::string_view line)
{
    VciStartLine r;
    r.kindKnown = true;
    r.kind = VciMessageKind::Response;
    const size_t sp = line.find(' ');
    const std::string_view version = line.substr(0, sp);
    if (version != kVciVersion)
        return bad(r, VciErrorCode::UnsupportedVersion, "unsupported protocol " + quoted(version) + " (expected VCI/1.0)");
    if (sp == std::string_view::npos)
        return bad(r, VciErrorCode::BadStartLine, "status line " + quoted(line) + " has no status code");
    const std::string_view rest = line.substr(sp + 1);
    if (rest.size() < 3 || (rest.size() > 3 && rest[3] != ' '))
        return bad(r, VciErrorCode::BadStartLine, "status line " + quoted(line) + " needs a three-digit status code");
    int status = 0;
    for (size_t i = 0; i < 3; ++i) {
        if (rest[i] < '0' || rest[i] > '9')
            return bad(r, VciErrorCode::BadStartLine, "status line " + quoted(line) + " needs a three-digit status code");
        status = status * 10 + (rest[i] - '0');
    }
    if (status < 100 || status > 599)
        return bad(r, VciErrorCode::BadStartLine, "status code " + std::to_string(status) + " is outside 100-599");
    for (char c : rest) {
        const auto u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\t') || u == 0x7f)
            return bad(r, VciErrorCode::BadStartLine, "status line " + quoted(line) + " holds a control character");
    }
    r.status = status;
    r.reason = rest.size() > 4 ? rest.substr(4) : std::string_view();
    r.ok = true;
    return r;
}

VciStartLine parseRequestLine(std::string_view line)
{
    VciStartLine r;
    const size_t sp1 = line.find(' ');
    const size_t sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
    if (sp2 == std::string_view::npos || line.find(' ', sp2 + 1) != std::string_view::npos)
        return bad(r, VciErrorCode::BadStartLine,
                   "start line " + quoted(line) + " is neither \"VERB /uri VCI/1.0\" nor \"VCI/1.0 status reason\"");
    const std::string_view verb = line.substr(0, sp1);
    const std::string_view uri = line.substr(sp1 + 1, sp2 - sp1 - 1);
    const std::string_view version = line.substr(sp2 + 1);
    if (!isVciToken(verb))
        return bad(r, VciErrorCode::BadStartLine, "request line " + quoted(line) + " does not start with a verb");
    r.kindKnown = true;
    r.verbText = verb;
    r.uri = uri;
    if (version != kVciVersion) {
        if (version.substr(0, 4) == "VCI/")
            return bad(r, VciErrorCode::UnsupportedVersion, "unsupported protocol " + quoted(version) + " (expected VCI/1.0)");
        return bad(r, VciErrorCode::BadStartLine, "request line " + quoted(line) + " does not end with VCI/1.0");
    }
    for (char c : uri) {
        const auto u = static_cast<unsigned char>(c);
        if (u <= 0x20 || u >= 0x7f)
            return bad(r, VciErrorCode::BadUri, "URI " + quoted(uri) + " holds a character that must be percent-encoded");
    }
    const auto known = verbFromName(verb);
    if (!known)
        return bad(r, VciErrorCode::UnknownVerb, "verb " + quoted(verb) + " is not one of GET, PUT, SUBSCRIBE, UNSUBSCRIBE, NOTIFY");
    r.verb = *known;
    if (uri == "*") {
        if (r.verb != VciVerb::Unsubscribe)
            return bad(r, VciErrorCode::BadUri, "URI \"*\" is only valid with UNSUBSCRIBE");
    } else if (uri.empty() || uri[0] != '/') {
        return bad(r, VciErrorCode::BadUri, "URI " + quoted(uri) + " must start with '/'");
    }
    r.ok = true;
    return r;
}

} // namespace

VciStartLine parseVciStartLine(std::string_view line)
{
    if (line.substr(0, 4) == "VCI/")
        return parseStatusLine(line);
    return parseRequestLine(line);
}

} // namespace sortie::vci
