#include "VciDump.h"

namespace sortie::vci {

nlohmann::json vciDumpLine(const VciMessage &m)
{
    nlohmann::json line;
    line["offset"] = m.offset;
    line["size"] = m.size;
    if (m.isRequest()) {
        line["kind"] = "request";
        line["verb"] = std::string(toString(m.verb));
        line["uri"] = m.uri;
    } else {
        line["kind"] = "response";
        line["status"] = m.status;
        line["reason"] = m.reason;
    }
    nlohmann::json headers = nlohmann::json::array();
    for (const auto &[name, value] : m.headers.entries())
        headers.push_back({name, value});
    line["headers"] = std::move(headers);
    if (m.jsonBody)
        line["body"] = m.body;
    else if (m.hasBody)
        line["rawBody"] = m.rawBody;
    return line;
}

nlohmann::json vciDumpLine(const VciParseError &e)
{
    nlohmann::json line;
    line["offset"] = e.offset;
    line["kind"] = "error";
    line["error"] = std::string(toString(e.code));
    line["message"] = e.message;
    if (e.kindKnown)
        line["messageKind"] = e.kind == VciMessageKind::Request ? "request" : "response";
    if (!e.verb.empty())
        line["verb"] = e.verb;
    if (!e.uri.empty())
        line["uri"] = e.uri;
    if (const int reply = e.replyStatus())
        line["reply"] = reply;
    return line;
}

nlohmann::json vciDumpLine(const VciParser::Result &result)
{
    return std::visit([](const auto &r) { return vciDumpLine(r); }, result);
}

} // namespace sortie::vci
