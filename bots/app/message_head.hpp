#pragma once
// What carrom-load reads of a server message before it decides what to do with it: the top-level
// "type", an event's "kind", and of a snapshot the fields its lag figures need
// (docs/server-load.md, "What is measured"), read with simdjson's On-Demand parser: any key order
// and any whitespace read the same. (Not nlohmann::json, proto's reader: its parsers cost the load
// tool 7-20 % more CPU per message; a delta is most of what it receives.)

#include "carrom/proto/codec.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace carrom::load {

// The fields of one snapshot that carrom-load uses.
struct SnapshotFields {
    bool keyframe = false;
    double t_s = 0.0; // "t" of a delta: the match time of its state, s (0 for a keyframe)
    // "due_ms" of a delta: the server's steady clock (ms) when the room's schedule had it due.
    std::optional<std::int64_t> due_ms;
    friend bool operator==(const SnapshotFields&, const SnapshotFields&) = default;
};

struct MessageHead {
    std::string type;        // top-level "type"
    std::string kind;        // an event's "kind" ("" for other types)
    SnapshotFields snapshot; // when type is "snapshot"
    friend bool operator==(const MessageHead&, const MessageHead&) = default;
};

// Reads a server message's text up to the point where its head is known: "type", then an event's
// "kind", a keyframe's "keyframe" (carrom-load reads nothing else of a keyframe); a delta is read
// whole. What follows the head is not read: carrom-load decodes the messages it acts on whole with
// proto::decode_server. Every value read up to the head is checked whole, so text that breaks the
// JSON grammar there is refused. Errors carry proto's codes: malformed_json (not JSON, a NUL
// byte, text after the object; simdjson's sentence, and the byte where simdjson stands when it
// names one), not_object, missing_type (no string "type"), bad_field (an event without a
// string "kind"; a snapshot without a boolean "keyframe"; a delta without a number "t", or with a
// "due_ms" that is not an integer).
proto::DecodedMessage<MessageHead> read_message_head(std::string_view text);

} // namespace carrom::load
