#pragma once
// Text encoding and validating decoding of every message. Decoding never throws: any input,
// however malformed or hostile, gives either a message whose every field is in range or an Error
// with a stable code (see error.hpp). Unknown fields are ignored; missing required fields,
// wrong types, out-of-range numbers, over-long strings and arrays are "bad_field" errors that
// name the field. JSON cannot carry NaN or infinity: numbers that overflow a double (1e400) are
// rejected by the parser ("malformed_json"); integers must be written without a fraction or
// exponent ("turn": 3, not 3.0).

#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/error.hpp"
#include "carrom/proto/limits.hpp"
#include "carrom/proto/server_messages.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace carrom::proto {

// A decoded wire message or the protocol error that refused it. (Documents and scenes decode
// to scene_json.hpp's Decoded, which carries an optional Error with its path.)
template <class T> struct DecodedMessage {
    std::optional<T> message; // set on success
    Error error;              // set on failure (code non-empty)
    bool ok() const { return message.has_value(); }
};

// Compact JSON text (one WebSocket text frame). Values must be finite (the server's are).
std::string encode(const ClientMessage& message);
std::string encode(const ServerMessage& message);

DecodedMessage<ClientMessage> decode_client(std::string_view text,
                                            std::size_t max_bytes = kMaxClientMessageBytes);
DecodedMessage<ServerMessage> decode_server(std::string_view text,
                                            std::size_t max_bytes = kMaxServerMessageBytes);

// Builds an error message's text directly (for paths that must not fail).
std::string encode_error(std::string_view code, std::string_view message);

// Rounds to 1/100 (px or px/s) so snapshots stay short; the server quantises snapshot values.
double quantise(double value);

} // namespace carrom::proto
