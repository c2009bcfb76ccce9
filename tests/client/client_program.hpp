#pragma once
// carrom-client as a child process of a client test (CARROM_CLIENT_PATH): its command line and
// its environment.

#include <cstdlib>
#include <string>
#include <vector>

namespace carrom::client {

// carrom-client with args, under `xvfb-run -a` (a 1280x1024x24 screen) when no DISPLAY is set.
inline std::vector<std::string> client_argv(const std::vector<std::string>& args) {
    std::vector<std::string> argv;
    if (std::getenv("DISPLAY") == nullptr) {
        argv = {"xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"};
    }
    argv.push_back(CARROM_CLIENT_PATH);
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
}

// The environment's ASAN_OPTIONS plus detect_leaks=0: under AddressSanitizer the client runs
// without the leak check, because Mesa's GL driver leaks a few hundred bytes per process (from a
// module it unloads at exit, so LeakSanitizer cannot suppress them by name; a bare SFML window
// shows the same). Every other ASan and UBSan check stays on.
inline std::string client_asan_options() {
    const char* now = std::getenv("ASAN_OPTIONS");
    return std::string("ASAN_OPTIONS=") + (now != nullptr ? now : "") + ":detect_leaks=0";
}

} // namespace carrom::client
