#pragma once
// Shared by the fuzz harnesses (tests/fuzz/*_fuzz.cpp) and the corpus replay (replay_main.cpp).
// Nothing here includes proto/ headers: codec_fuzz.cpp and scene_fuzz.cpp must stay separate
// translation units, as codec.hpp and scene_json.hpp both define carrom::proto::Decoded.

#include <cstddef>
#include <cstdint>
#include <string_view>

// libFuzzer's entry point. Each harness executable (clang + libFuzzer, or the g++ replay) links
// exactly one definition: codec_target.cpp or room_fuzz.cpp.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace carrom::fuzz {

// A harness check failed: prints "carrom fuzz: <what>" and, if given, the offending text
// (truncated, non-printable bytes escaped) to stderr, then aborts, which libFuzzer reports as a
// crash and the replay test as a failed test.
[[noreturn]] void fail(std::string_view what, std::string_view text = {});

// The codec target's two halves (codec_fuzz.cpp, scene_fuzz.cpp).
void codec_one_input(bool server_side, std::string_view text);
void scene_one_input(std::string_view text);

} // namespace carrom::fuzz
