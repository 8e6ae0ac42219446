// The seeds of a libFuzzer target, run once each through its entry point in a build without
// libFuzzer (g++), as `fuzz_x -runs=0 CORPUS` does in the fuzz build: a seed that crashes, trips an
// assertion or a sanitizer fails the run. Standard library only, so it links with the Qt-free
// codecs' targets too. Usage: seeds_fuzz_x FOLDER|FILE ... ; prints how many inputs ran.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

namespace {

std::vector<std::filesystem::path> inputsOf(const std::filesystem::path &argument)
{
    if (!std::filesystem::is_directory(argument))
        return {argument};
    std::vector<std::filesystem::path> files;
    for (const auto &entry : std::filesystem::directory_iterator(argument))
        if (entry.is_regular_file())
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());  // the same order every run, so a failure repeats
    return files;
}

} // namespace

int main(int argc, char **argv)
{
    size_t ran = 0;
    for (int i = 1; i < argc; ++i) {
        for (const auto &path : inputsOf(argv[i])) {
            std::ifstream in(path, std::ios::binary);
            if (!in) {
                std::fprintf(stderr, "seeds: cannot read %s\n", path.c_str());
                return 1;
            }
            const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t *>(bytes.data()), bytes.size());
            ++ran;
        }
    }
    std::printf("seeds: ran %zu inputs\n", ran);
    return ran > 0 ? 0 : 1;  // no seed at all is a failure, not a pass
}
