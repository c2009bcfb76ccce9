// Fuzzes the message codec (proto/codec.hpp) with arbitrary text as a client message
// (decode_client) or a server message (decode_server). Decoding must never throw or crash; a
// message it accepts is encoded again, and that text must decode to an equal message.
// Failures: a sanitizer report, an exception (libFuzzer reports it as a crash), or a failed
// round trip (fuzz::fail, which aborts).
#include "carrom/proto/codec.hpp"
#include "fuzz.hpp"

#include <string>

namespace carrom::fuzz {
namespace {

template <class Decode> void round_trip(Decode decode, std::string_view text) {
    const auto decoded = decode(text);
    if (!decoded.ok()) {
        return;
    }
    const std::string encoded = proto::encode(*decoded.message);
    const auto again = decode(encoded);
    if (!again.ok()) {
        fail("codec: the encoding of a decoded message does not decode (" + again.error.code +
                 ": " + again.error.message + ")",
             encoded);
    }
    if (!(*again.message == *decoded.message)) {
        fail("codec: a decoded message changes in an encode/decode round trip", encoded);
    }
}

} // namespace

void codec_one_input(bool server_side, std::string_view text) {
    if (server_side) {
        round_trip([](std::string_view t) { return proto::decode_server(t); }, text);
    } else {
        round_trip([](std::string_view t) { return proto::decode_client(t); }, text);
    }
}

} // namespace carrom::fuzz
