#include "player_name_key.hpp"

#include <utf8proc.h>

#include <cstdlib>
#include <memory>

namespace carrom::server {

std::optional<std::string> player_name_key(std::string_view name) {
    utf8proc_uint8_t* folded = nullptr;
    const utf8proc_ssize_t length = utf8proc_map(
        reinterpret_cast<const utf8proc_uint8_t*>(name.data()),
        static_cast<utf8proc_ssize_t>(name.size()), &folded,
        static_cast<utf8proc_option_t>(UTF8PROC_STABLE | UTF8PROC_COMPOSE | UTF8PROC_COMPAT |
                                       UTF8PROC_CASEFOLD | UTF8PROC_IGNORE));
    if (length < 0) {
        return std::nullopt; // invalid UTF-8 (or out of memory)
    }
    const std::unique_ptr<utf8proc_uint8_t, decltype(&std::free)> owned(folded, &std::free);
    std::string key;
    bool space = false;
    for (utf8proc_ssize_t i = 0; i < length; ++i) {
        const char c = static_cast<char>(folded[i]);
        if (c == ' ' || c == '\t') {
            space = !key.empty();
            continue;
        }
        if (space) {
            key.push_back(' ');
            space = false;
        }
        key.push_back(c);
    }
    if (key.empty()) {
        return std::nullopt;
    }
    return key;
}

} // namespace carrom::server
