#include "VciWriter.h"

namespace sortie::vci {

bool VciWriter::isValidUri(std::string_view uri)
{
    if (uri == "*")
        return true;
    if (uri.empty() || uri[0] != '/')
        return false;
    for (char c : uri) {
        const auto u = static_cast<unsigned char>(c);
        if (u <= 0x20 || u >= 0x7f)
            return false;
    }
    return true;
}

void VciWriter::appendRequest(std::string &out, VciVerb verb, std::string_view uri, const nlohmann::json *body,
                              const VciHeaders *extra) const
{
    out += toString(verb);
    out += ' ';
    out += uri;
    out += ' ';
    out += kVciVersion;
    out += "\r\n";
    appendHeadersAndBody(out, body, extra);
}

void VciWriter::appendResponse(std::string &out, int status, std::string_view reason, const nlohmann::json *body,
                               const VciHeaders *extra) const
{
    out += kVciVersion;
    out += ' ';
    out += std::to_string(status);
    out += ' ';
    out += reason.empty() ? reasonPhrase(status) : reason;
    out += "\r\n";
    appendHeadersAndBody(out, body, extra);
}

void VciWriter::appendHeadersAndBody(std::string &out, const nlohmann::json *body, const VciHeaders *extra) const
{
    std::string text;
    if (body) {
        // Replace rather than throw on a string that is not UTF-8: a peer must never get half a message.
        text = body->dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        out += "Content-Type: application/json\r\n";
        if (m_framing == VciFraming::ContentLength) {
            out += "Content-Length: ";
            out += std::to_string(text.size());
            out += "\r\n";
        } else if (body->is_number()) {
            text += ' '; // a bare number ends at one whitespace character
        }
    }
    if (extra) {
        for (const auto &[name, value] : extra->entries()) {
            out += name;
            out += ": ";
            out += value;
            out += "\r\n";
        }
    }
    out += "\r\n";
    out += text;
}

std::string VciWriter::request(VciVerb verb, std::string_view uri, const nlohmann::json *body) const
{
    std::string out;
    appendRequest(out, verb, uri, body);
    return out;
}

std::string VciWriter::response(int status, const nlohmann::json *body) const
{
    std::string out;
    appendResponse(out, status, {}, body);
    return out;
}

} // namespace sortie::vci
