#pragma once

#include "VciHeaders.h"
#include "VciTypes.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace sortie::vci {

// How a JSON body is delimited on the wire. Both are valid VCI; a reader must accept either.
enum class VciFraming : uint8_t {
    ContentLength, // Content-Type and Content-Length (what Sortie sends by default)
    JsonOnly,      // Content-Type alone: the JSON tells its end (a number gets one trailing space)
};

// Writes VCI messages. Pure: appends bytes to a string. A null `body` pointer means no body; any JSON
// value (null, true, 3.5, "text", [..], {..}) is a body. `extra` headers are written after the
// framing ones. The URI is written as given: callers pass "/path" or "*" (VciConnection checks).
class VciWriter
{
public:
    explicit VciWriter(VciFraming framing = VciFraming::ContentLength) : m_framing(framing) {}

    void appendRequest(std::string &out, VciVerb verb, std::string_view uri, const nlohmann::json *body = nullptr,
                       const VciHeaders *extra = nullptr) const;
    void appendResponse(std::string &out, int status, std::string_view reason = {}, const nlohmann::json *body = nullptr,
                        const VciHeaders *extra = nullptr) const;

    std::string request(VciVerb verb, std::string_view uri, const nlohmann::json *body = nullptr) const;
    std::string response(int status, const nlohmann::json *body = nullptr) const;

    VciFraming framing() const { return m_framing; }
    void setFraming(VciFraming framing) { m_framing = framing; }

    // A URI Sortie may put on a request line: "/" then printable ASCII without spaces, or "*".
    static bool isValidUri(std::string_view uri);

private:
    void appendHeadersAndBody(std::string &out, const nlohmann::json *body, const VciHeaders *extra) const;

    VciFraming m_framing;
};

} // namespace sortie::vci
