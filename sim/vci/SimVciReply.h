#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace sortie::sim {

// What a simulated vehicle answers to one request.
struct SimVciReply
{
    int status = 200;
    std::optional<nlohmann::json> body;

    static SimVciReply ok(nlohmann::json body) { return {200, std::move(body)}; }
    static SimVciReply okEmpty() { return {200, std::nullopt}; }
    static SimVciReply error(int status, const std::string &why) { return {status, nlohmann::json{{"error", why}}}; }
};

} // namespace sortie::sim
