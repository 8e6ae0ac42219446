#include "VciTypes.h"

namespace sortie::vci {

std::string_view toString(VciVerb verb)
{
    switch (verb) {
    case VciVerb::Get: return "GET";
    case VciVerb::Put: return "PUT";
    case VciVerb::Subscribe: return "SUBSCRIBE";
    case VciVerb::Unsubscribe: return "UNSUBSCRIBE";
    case VciVerb::Notify: return "NOTIFY";
    }
    return "?";
}

std::optional<VciVerb> verbFromName(std::string_view name)
{
    switch (name.size()) {
    case 3:
        if (name == "GET") return VciVerb::Get;
        if (name == "PUT") return VciVerb::Put;
        break;
    case 6:
        if (name == "NOTIFY") return VciVerb::Notify;
        break;
    case 9:
        if (name == "SUBSCRIBE") return VciVerb::Subscribe;
        break;
    case 11:
        if (name == "UNSUBSCRIBE") return VciVerb::Unsubscribe;
        break;
    default:
        break;
    }
    return std::nullopt;
}

std::string_view reasonPhrase(int status)
{
    switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 500: return "Internal Server Error";
    case 501: return "Not Implemented";
    default: break;
    }
    switch (status / 100) {
    case 2: return "Success";
    case 4: return "Client Error";
    case 5: return "Server Error";
    default: return "Unknown";
    }
}

} // namespace sortie::vci
