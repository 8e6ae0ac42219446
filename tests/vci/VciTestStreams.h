#pragma once

// Helpers shared by the VCI parser tests: run a parser over a stream in given chunks and describe
// each result in one comparable line.
#include "VciDump.h"
#include "VciParser.h"

#include <string>
#include <vector>

namespace sortie::vci::test {

inline std::vector<VciParser::Result> parseChunked(const std::string &stream, const std::vector<size_t> &cuts,
                                                   VciLimits limits = {})
{
    VciParser parser(limits);
    std::vector<VciParser::Result> out;
    size_t from = 0;
    auto drain = [&] {
        while (auto r = parser.next())
            out.push_back(std::move(*r));
    };
    for (size_t cut : cuts) {
        parser.feed(std::string_view(stream).substr(from, cut - from));
        drain();
        from = cut;
    }
    parser.feed(std::string_view(stream).substr(from));
    drain();
    return out;
}

inline std::vector<VciParser::Result> parseAll(const std::string &stream, VciLimits limits = {})
{
    return parseChunked(stream, {}, limits);
}

inline std::string describe(const std::vector<VciParser::Result> &results)
{
    std::string s;
    for (const auto &r : results)
        s += vciDumpLine(r).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    return s;
}

} // namespace sortie::vci::test
