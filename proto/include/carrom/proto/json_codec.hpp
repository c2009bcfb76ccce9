#pragma once
// The same encoding as codec.hpp, as nlohmann::json values (for tools and tests that embed or
// inspect messages). Kept apart so most users do not include nlohmann/json.hpp.

#include "carrom/proto/codec.hpp"

#include <nlohmann/json.hpp>

namespace carrom::proto {

nlohmann::json to_json(const ClientMessage& message);
nlohmann::json to_json(const ServerMessage& message);

// Validating decoders from an already-parsed value (never throw).
DecodedMessage<ClientMessage> client_from_json(const nlohmann::json& value);
DecodedMessage<ServerMessage> server_from_json(const nlohmann::json& value);

} // namespace carrom::proto
