// The "codec" fuzz target's entry point. The first byte picks the harness, the rest is its text:
//   0: a client message (codec_fuzz.cpp, decode_client)
//   1: a server message (codec_fuzz.cpp, decode_server)
//   2: a scene file (scene_fuzz.cpp, decode_scene_text, then the exact engine)
// (the byte is taken modulo 3). Failures are those of the harnesses; an empty input is ignored.
#include "fuzz.hpp"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) {
        return 0;
    }
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    switch (data[0] % 3) {
    case 0:
        carrom::fuzz::codec_one_input(false, text);
        break;
    case 1:
        carrom::fuzz::codec_one_input(true, text);
        break;
    default:
        carrom::fuzz::scene_one_input(text);
        break;
    }
    return 0;
}
