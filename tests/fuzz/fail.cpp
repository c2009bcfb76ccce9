// carrom::fuzz::fail (fuzz.hpp): the one way a harness reports a failed check.
#include "fuzz.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace carrom::fuzz {

void fail(std::string_view what, std::string_view text) {
    std::fprintf(stderr, "carrom fuzz: %.*s\n", static_cast<int>(what.size()), what.data());
    if (!text.empty()) {
        constexpr std::size_t kShown = 600;
        std::fputs("  text: ", stderr);
        for (const char c : text.substr(0, std::min(text.size(), kShown))) {
            const auto byte = static_cast<unsigned char>(c);
            if (byte >= 0x20 && byte < 0x7f) {
                std::fputc(c, stderr);
            } else {
                std::fprintf(stderr, "\\x%02x", static_cast<unsigned>(byte));
            }
        }
        if (text.size() > kShown) {
            std::fprintf(stderr, "... (%zu bytes)", text.size());
        }
        std::fputc('\n', stderr);
    }
    std::fflush(stderr);
    std::abort();
}

} // namespace carrom::fuzz
