#pragma once
// A direct writer for the one hot message: "snapshot" (per moving room, one at every change of
// motion and --snapshot-hz, default 10, a second in between). It writes the same JSON object as
// proto::encode (keys in another order; numbers in their shortest round-trip form with
// std::to_chars) without building a JSON tree, so it costs a fraction of the generic encoder.
// tests/room/snapshot_writer_test.cpp checks that proto::decode_server reads it back equal to the
// input.

#include "carrom/proto/server_messages.hpp"

#include <string>

namespace carrom::room {

std::string encode_snapshot(const proto::Snapshot& snapshot);

} // namespace carrom::room
