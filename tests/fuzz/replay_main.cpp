// Replays fuzz inputs through a harness's LLVMFuzzerTestOneInput without libFuzzer, so the
// committed corpora run as ordinary tests under g++ (and the asan preset's sanitizers). Linked
// with one harness: carrom_fuzz_replay_codec, carrom_fuzz_replay_room.
//   carrom_fuzz_replay_room                  replays the committed corpus (CARROM_FUZZ_CORPUS)
//   carrom_fuzz_replay_room FILE_OR_DIR...   replays those inputs (e.g. a libFuzzer crash file)
// Fails (exit 1) if a directory is missing or holds no inputs; a failing input aborts the process
// after its path is printed.
#include "fuzz.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

#ifndef CARROM_FUZZ_CORPUS
#error "CARROM_FUZZ_CORPUS (the committed corpus directory) must be defined"
#endif

namespace {

namespace fs = std::filesystem;

// The input being replayed, for the abort handler (set before each input).
char g_current[4096] = "";

void on_abort(int signal_number) {
    const char prefix[] = "carrom fuzz replay: failed on input ";
    (void)!write(STDERR_FILENO, prefix, sizeof prefix - 1);
    (void)!write(STDERR_FILENO, g_current, std::strlen(g_current));
    (void)!write(STDERR_FILENO, "\n", 1);
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
}

bool collect(const fs::path& path, std::vector<fs::path>& out) {
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) {
        out.push_back(path);
        return true;
    }
    if (!fs::is_directory(path, ec)) {
        std::fprintf(stderr, "carrom fuzz replay: %s is neither a file nor a directory\n",
                     path.c_str());
        return false;
    }
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(path, ec)) {
        if (entry.is_regular_file()) {
            files.push_back(entry.path());
        }
    }
    if (ec || files.empty()) {
        std::fprintf(stderr, "carrom fuzz replay: no inputs in %s\n", path.c_str());
        return false;
    }
    std::sort(files.begin(), files.end());
    out.insert(out.end(), files.begin(), files.end());
    return true;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<fs::path> inputs;
    std::vector<fs::path> roots;
    for (int i = 1; i < argc; ++i) {
        roots.emplace_back(argv[i]);
    }
    if (roots.empty()) {
        roots.emplace_back(CARROM_FUZZ_CORPUS);
    }
    for (const auto& root : roots) {
        if (!collect(root, inputs)) {
            return 1;
        }
    }
    std::signal(SIGABRT, on_abort);
    const auto start = std::chrono::steady_clock::now();
    std::size_t bytes = 0;
    for (const auto& path : inputs) {
        const std::string name = path.string();
        const std::size_t n = std::min(name.size(), sizeof g_current - 1);
        std::memcpy(g_current, name.data(), n);
        g_current[n] = '\0';
        std::ifstream file(path, std::ios::binary);
        const std::vector<char> data((std::istreambuf_iterator<char>(file)),
                                     std::istreambuf_iterator<char>());
        if (!file.good() && !file.eof()) {
            std::fprintf(stderr, "carrom fuzz replay: cannot read %s\n", name.c_str());
            return 1;
        }
        bytes += data.size();
        // A copy of exactly the input's size, so ASan sees any read past its end.
        const auto copy = std::make_unique<std::uint8_t[]>(std::max<std::size_t>(data.size(), 1));
        std::copy(data.begin(), data.end(), copy.get());
        LLVMFuzzerTestOneInput(copy.get(), data.size());
    }
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                        std::chrono::steady_clock::now() - start)
                        .count();
    std::printf("carrom fuzz replay: %zu inputs (%zu bytes) passed in %lld ms\n", inputs.size(),
                bytes, static_cast<long long>(ms));
    return 0;
}
