#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace sortie::vci {

// The request verbs of VCI/1.0. Anything else on a start line is answered 501.
enum class VciVerb : uint8_t { Get, Put, Subscribe, Unsubscribe, Notify };

std::string_view toString(VciVerb verb);
std::optional<VciVerb> verbFromName(std::string_view name); // case-sensitive, like HTTP methods

enum class VciMessageKind : uint8_t { Request, Response };

// The status codes the spec defines. Others are carried as plain numbers (VciStatus is open).
enum class VciStatus : int {
    Ok = 200,
    BadRequest = 400,
    InternalServerError = 500,
    NotImplemented = 501,
};

// The spec's reason phrase for a status code ("OK", "Bad Request", ...), or a generic one by class.
std::string_view reasonPhrase(int status);

inline constexpr std::string_view kVciVersion = "VCI/1.0";

// What the parser accepts before it calls a message bad. Each limit bounds memory: nothing larger is
// ever buffered, and a message over a limit is reported and skipped (docs/vci-profile.md, "Limits").
struct VciLimits
{
    size_t maxLineLength = 8 * 1024;         // a start or header line, line ending included
    size_t maxHeaders = 100;                 // header lines per message
    size_t maxBodySize = 16 * 1024 * 1024;   // body bytes, by Content-Length or by JSON
    size_t maxJsonDepth = 256;               // nested arrays and objects
    size_t maxNumberLength = 512;             // characters in one JSON number
    size_t maxDecodedBytes = 192 * 1024 * 1024; // what a JSON body may take in memory (VciJsonReader)
};

} // namespace sortie::vci
