#include "carrom/net/identity_file.hpp"

#include "carrom/proto/types.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/random.h>
#include <unistd.h>

namespace carrom::net {

namespace {

// 32 bytes from getrandom as 64 lowercase hex digits; none when the CSPRNG fails.
std::optional<std::string> new_identity_key() {
    std::uint8_t bytes[32];
    std::size_t filled = 0;
    while (filled < sizeof bytes) {
        const ssize_t got = ::getrandom(bytes + filled, sizeof bytes - filled, 0);
        if (got < 0) {
            if (errno == EINTR) {
                continue;
            }
            return std::nullopt;
        }
        filled += static_cast<std::size_t>(got);
    }
    static constexpr char kHex[] = "0123456789abcdef";
    std::string key;
    for (const std::uint8_t b : bytes) {
        key.push_back(kHex[b >> 4]);
        key.push_back(kHex[b & 0x0f]);
    }
    return key;
}

LoadedIdentity failed(std::string message) {
    LoadedIdentity out;
    out.error = std::move(message);
    return out;
}

} // namespace

LoadedIdentity load_or_create_identity(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(path, ec)) {
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        std::string key = text.str();
        if (!key.empty() && key.back() == '\n') {
            key.pop_back();
        }
        if (!in || !proto::is_identity_key(key)) {
            return failed(path + " does not hold a player key (64 lowercase hexadecimal digits).");
        }
        return LoadedIdentity{key, false, std::nullopt};
    }
    const auto key = new_identity_key();
    if (!key) {
        return failed("cannot draw a player key from the operating system's random source.");
    }
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::exists(parent, ec)) {
        fs::create_directories(parent, ec);
        fs::permissions(parent, fs::perms::owner_all, ec);
        if (ec) {
            return failed("cannot create " + parent.string() + ": " + ec.message() + ".");
        }
    }
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) {
        return failed("cannot create " + path + ": " + std::strerror(errno) + ".");
    }
    const std::string line = *key + "\n";
    const bool written = ::write(fd, line.data(), line.size()) == static_cast<ssize_t>(line.size());
    const bool closed = ::close(fd) == 0;
    if (!written || !closed) {
        return failed("cannot write " + path + ".");
    }
    return LoadedIdentity{*key, true, std::nullopt};
}

std::string default_identity_path() {
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    if (xdg != nullptr && *xdg != '\0') {
        return std::string(xdg) + "/carrom/identity";
    }
    const char* home = std::getenv("HOME");
    if (home != nullptr && *home != '\0') {
        return std::string(home) + "/.config/carrom/identity";
    }
    return {};
}

} // namespace carrom::net
