// The direct snapshot writer against the generic codec.
#include "carrom/room/snapshot_writer.hpp"

#include "carrom/proto/codec.hpp"

#include <gtest/gtest.h>

namespace carrom::room {
namespace {

TEST(SnapshotWriter, DecodesToTheSameSnapshot) {
    proto::Snapshot snap;
    snap.seq = 12345;
    snap.turn = 7;
    snap.t_s = 0.016;
    snap.bodies = {proto::SnapshotBody{19, {300.12, 401.5}, {-12.5, -600.0}},
                   proto::SnapshotBody{0, {250.0, 0.01}, {0.0, -0.0}},
                   proto::SnapshotBody{3, {599.99, 1e-2}, {12345.67, 4500.0}}};
    snap.pocketed = {4, 18};
    auto check = [](const proto::Snapshot& s) {
        const std::string text = encode_snapshot(s);
        const auto decoded = proto::decode_server(text);
        ASSERT_TRUE(decoded.ok()) << decoded.error.message << ": " << text;
        EXPECT_EQ(*decoded.message, proto::ServerMessage{s}) << text;
    };
    check(snap);
    snap.due_ms = 1700000000123;
    check(snap);
    EXPECT_NE(encode_snapshot(snap).find(R"("due_ms":1700000000123})"), std::string::npos);
    snap.keyframe = true;
    snap.bodies.clear();
    snap.pocketed.clear();
    snap.due_ms.reset();
    check(snap);
    EXPECT_EQ(encode_snapshot(snap),
              R"({"type":"snapshot","seq":12345,"turn":7,"t":0.016,"keyframe":true,)"
              R"("bodies":[],"pocketed":[]})");
}

} // namespace
} // namespace carrom::room
