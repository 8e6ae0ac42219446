// sortie-dump: decodes a captured HCI byte stream (a file, or stdin with "-" or no argument) into JSON
// lines on stdout, one per frame; or a VCI stream (--vci, or recognised by its first line), one line
// per message or error. Wiring only; the decoding is HciDumpWriter's and VciDumpWriter's.
#include "HciDumpWriter.h"
#include "VciDumpWriter.h"

#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace {

void usage()
{
    std::fprintf(stderr,
                 "usage: sortie-dump [--reveal-secrets] [--vci] [FILE|-]\n"
                 "Decodes an HCI byte stream into one JSON line per frame: offset, instanceId, type, message and\n"
                 "the message as protobuf JSON; dropped frames are lines with \"dropped\" and \"detail\".\n"
                 "Passwords show as \"***\" unless --reveal-secrets is given.\n"
                 "A VCI stream (--vci, or one that starts with a VCI start line) gives one JSON line per message:\n"
                 "offset, kind, verb or status, uri, headers, body; errors are lines with kind \"error\".\n");
}

} // namespace

int main(int argc, char **argv)
{
    sortie::dump::HciDumpWriter::Options options;
    std::string path = "-";
    bool vci = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--reveal-secrets")) {
            options.revealSecrets = true;
        } else if (!std::strcmp(argv[i], "--vci")) {
            vci = true;
        } else if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
            usage();
            return 0;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            std::fprintf(stderr, "sortie-dump: unknown option %s\n", argv[i]);
            usage();
            return 2;
        } else {
            path = argv[i];
        }
    }
    std::FILE *in = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
    if (!in) {
        std::fprintf(stderr, "sortie-dump: %s: %s\n", path.c_str(), std::strerror(errno));
        return 1;
    }
    std::ios::sync_with_stdio(false);
    std::vector<char> chunk(64 * 1024);
    size_t n = std::fread(chunk.data(), 1, chunk.size(), in);
    const std::string_view first(chunk.data(), n);
    for (const char *start : {"GET ", "PUT ", "SUBSCRIBE ", "UNSUBSCRIBE ", "NOTIFY ", "VCI/"})
        vci = vci || first.substr(0, std::strlen(start)) == start;
    sortie::dump::HciDumpWriter hciWriter(std::cout, options);
    sortie::vci::VciDumpWriter vciWriter(std::cout);
    for (; n > 0; n = std::fread(chunk.data(), 1, chunk.size(), in)) {
        if (vci)
            vciWriter.feed(std::string_view(chunk.data(), n));
        else
            hciWriter.feed(std::string_view(chunk.data(), n));
    }
    const bool readError = std::ferror(in);
    if (vci)
        vciWriter.finish();
    else
        hciWriter.finish();
    std::cout.flush();
    if (in != stdin)
        std::fclose(in);
    if (readError) {
        std::fprintf(stderr, "sortie-dump: %s: read error\n", path.c_str());
        return 1;
    }
    return 0;
}
