// The small pieces: write queue, rate limiter, tokens and codes, registry, metrics.
#include "carrom/proto/types.hpp"
#include "carrom/server/metrics.hpp"
#include "carrom/server/random.hpp"
#include "carrom/server/rate_limiter.hpp"
#include "carrom/server/registry.hpp"
#include "carrom/server/write_queue.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <vector>

namespace carrom::server {
namespace {

room::Outgoing text(std::string s, room::MessageKind kind = room::MessageKind::Normal) {
    return {std::make_shared<const std::string>(std::move(s)), kind};
}

TEST(WriteQueue, OneWriteInFlight) {
    WriteQueue q(1000, 4);
    EXPECT_EQ(q.push(text("a")), WriteQueue::Push::Queued);
    EXPECT_EQ(q.push(text("b")), WriteQueue::Push::Queued);
    auto first = q.start_write();
    ASSERT_TRUE(first);
    EXPECT_EQ(*first->text, "a");
    EXPECT_FALSE(q.start_write()); // a write is in flight
    q.finish_write();
    auto second = q.start_write();
    ASSERT_TRUE(second);
    EXPECT_EQ(*second->text, "b");
    q.finish_write();
    EXPECT_TRUE(q.empty());
    EXPECT_EQ(q.queued_bytes(), 0U);
}

TEST(WriteQueue, ANewerRoomStateReplacesTheWaitingOnes) {
    WriteQueue q(100, 8);
    ASSERT_EQ(q.push(text("state0", room::MessageKind::State)), WriteQueue::Push::Queued);
    ASSERT_TRUE(q.start_write()); // in flight: kept
    ASSERT_EQ(q.push(text("state1", room::MessageKind::State)), WriteQueue::Push::Queued);
    ASSERT_EQ(q.push(text("event")), WriteQueue::Push::Queued);
    // 1000 more room states never overflow a 100-byte queue: each replaces the one waiting.
    for (int i = 2; i < 1000; ++i) {
        ASSERT_EQ(q.push(text("state" + std::to_string(i), room::MessageKind::State)),
                  WriteQueue::Push::Queued);
    }
    EXPECT_EQ(q.queued_messages(), 3U);
    EXPECT_EQ(q.queued_bytes(), 6U + 5U + 8U);
    q.finish_write();
    auto next = q.start_write();
    ASSERT_TRUE(next);
    EXPECT_EQ(*next->text, "event");
    q.finish_write();
    next = q.start_write();
    ASSERT_TRUE(next);
    EXPECT_EQ(*next->text, "state999");
}

TEST(WriteQueue, SnapshotsAreDroppedUnderBackPressure) {
    WriteQueue q(1000, 2);
    EXPECT_EQ(q.push(text("s0", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    ASSERT_TRUE(q.start_write()); // in flight does not count as waiting
    EXPECT_EQ(q.push(text("s1", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    EXPECT_EQ(q.push(text("s2", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    EXPECT_EQ(q.waiting_snapshots(), 2U);
    EXPECT_EQ(q.push(text("s3", room::MessageKind::Snapshot)), WriteQueue::Push::DroppedSnapshot);
    EXPECT_EQ(q.push(text("3")), WriteQueue::Push::Queued); // normal messages still queue
    EXPECT_EQ(q.queued_messages(), 4U);
    // The in-flight snapshot finishes and the next starts: one snapshot waits, so a new one
    // queues again.
    q.finish_write();
    ASSERT_TRUE(q.start_write());
    EXPECT_EQ(q.waiting_snapshots(), 1U);
    EXPECT_EQ(q.push(text("s4", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
}

TEST(WriteQueue, CollisionCuesDoNotCountTowardTheSnapshotBacklog) {
    WriteQueue q(100000, 2);
    ASSERT_EQ(q.push(text("e0", room::MessageKind::Cue)), WriteQueue::Push::Queued);
    ASSERT_TRUE(q.start_write());
    for (int i = 0; i < 50; ++i) { // a break's burst of collision events, as the room sends them
        ASSERT_EQ(q.push(text("e", room::MessageKind::Cue)), WriteQueue::Push::Queued);
    }
    EXPECT_EQ(q.waiting_snapshots(), 0U);
    EXPECT_EQ(q.waiting_cues(), 50U);
    EXPECT_EQ(q.push(text("s1", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    EXPECT_EQ(q.push(text("s2", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    EXPECT_EQ(q.push(text("s3", room::MessageKind::Snapshot)), WriteQueue::Push::DroppedSnapshot);
    // Drain everything: the counts return to zero.
    q.finish_write();
    while (q.start_write()) {
        q.finish_write();
    }
    EXPECT_TRUE(q.empty());
    EXPECT_EQ(q.waiting_snapshots(), 0U);
    EXPECT_EQ(q.waiting_cues(), 0U);
    EXPECT_EQ(q.queued_bytes(), 0U);
}

TEST(WriteQueue, NormalMessagesDoNotCountTowardTheSnapshotBacklog) {
    WriteQueue q(100000, 1);
    ASSERT_EQ(q.push(text("n0")), WriteQueue::Push::Queued);
    ASSERT_TRUE(q.start_write());
    for (int i = 0; i < 20; ++i) {
        ASSERT_EQ(q.push(text("n")), WriteQueue::Push::Queued);
    }
    EXPECT_EQ(q.push(text("s1", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    EXPECT_EQ(q.push(text("s2", room::MessageKind::Snapshot)), WriteQueue::Push::DroppedSnapshot);
}

TEST(WriteQueue, CuesAreDroppedWhileTheClientIsBehindOnSnapshots) {
    WriteQueue q(100000, 2);
    ASSERT_EQ(q.push(text("s0", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    ASSERT_TRUE(q.start_write());
    ASSERT_EQ(q.push(text("s1", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    EXPECT_EQ(q.push(text("c1", room::MessageKind::Cue)),
              WriteQueue::Push::Queued); // 1 waits: not behind
    ASSERT_EQ(q.push(text("s2", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    EXPECT_EQ(q.push(text("c2", room::MessageKind::Cue)), WriteQueue::Push::DroppedCue); // 2 wait
    EXPECT_EQ(q.push(text("n")), WriteQueue::Push::Queued); // a normal message still queues
    EXPECT_EQ(q.waiting_cues(), 1U);
    // Once the client catches up (one snapshot written), cues queue again.
    q.finish_write();
    ASSERT_TRUE(q.start_write()); // s1 in flight, s2 waits
    EXPECT_EQ(q.push(text("c3", room::MessageKind::Cue)), WriteQueue::Push::Queued);
}

TEST(WriteQueue, CuesHaveTheirOwnBacklog) {
    WriteQueue q(100000, 8, 3);
    ASSERT_EQ(q.push(text("c0", room::MessageKind::Cue)), WriteQueue::Push::Queued);
    ASSERT_TRUE(q.start_write()); // the cue in flight does not count as waiting
    for (int i = 0; i < 3; ++i) {
        ASSERT_EQ(q.push(text("c", room::MessageKind::Cue)), WriteQueue::Push::Queued);
    }
    EXPECT_EQ(q.push(text("c4", room::MessageKind::Cue)), WriteQueue::Push::DroppedCue);
    EXPECT_EQ(q.push(text("s", room::MessageKind::Snapshot)), WriteQueue::Push::Queued);
    EXPECT_EQ(q.queued_messages(), 5U); // c0 in flight, 3 cues, the snapshot
}

TEST(WriteQueue, OverflowPastTheByteBound) {
    WriteQueue q(10, 100);
    EXPECT_EQ(q.push(text("12345")), WriteQueue::Push::Queued);
    EXPECT_EQ(q.push(text("67890")), WriteQueue::Push::Queued);
    EXPECT_EQ(q.push(text("x")), WriteQueue::Push::Overflow);
    EXPECT_EQ(q.queued_bytes(), 10U);
}

TEST(RateLimiter, BurstThenSustainedRate) {
    RateLimiter limiter(10.0, 3.0, 0);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Reject);
    EXPECT_EQ(limiter.on_message(99), RateLimiter::Verdict::Reject); // 0.99 tokens
    EXPECT_EQ(limiter.on_message(100), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(200), RateLimiter::Verdict::Accept);
}

TEST(RateLimiter, AFloodDisconnects) {
    RateLimiter limiter(1.0, 2.0, 0);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Reject);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Disconnect);
}

TEST(RateLimiter, AFloodReadSlowlyStillDisconnects) {
    // 500/s (half a token per ms), burst 3, a flood the server reads one message per ms: a
    // token comes back every other message, and those accepted messages do not forgive the
    // rejected ones in between.
    RateLimiter limiter(500.0, 3.0, 0);
    using V = RateLimiter::Verdict;
    std::vector<V> verdicts;
    for (std::int64_t t = 0; t < 20 && (verdicts.empty() || verdicts.back() != V::Disconnect);
         ++t) {
        verdicts.push_back(limiter.on_message(t));
    }
    EXPECT_EQ(verdicts, (std::vector<V>{V::Accept, V::Accept, V::Accept, V::Accept, V::Accept,
                                        V::Reject, V::Accept, V::Reject, V::Accept,
                                        V::Disconnect}));
}

TEST(RateLimiter, QuietUntilTheBucketIsFullForgivesEarlierRejections) {
    RateLimiter limiter(500.0, 2.0, 0);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Reject);
    // 4 ms of quiet refill both tokens: the rejection is forgotten.
    EXPECT_EQ(limiter.on_message(4), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(4), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(4), RateLimiter::Verdict::Reject);
    EXPECT_EQ(limiter.on_message(4), RateLimiter::Verdict::Disconnect);
}

TEST(RateLimiter, QuietShorterThanARefillForgivesNothing) {
    RateLimiter limiter(500.0, 2.0, 0);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Accept);
    EXPECT_EQ(limiter.on_message(0), RateLimiter::Verdict::Reject);
    EXPECT_EQ(limiter.on_message(3), RateLimiter::Verdict::Accept); // 1.5 tokens, not full
    EXPECT_EQ(limiter.on_message(3), RateLimiter::Verdict::Disconnect);
}

TEST(Random, TokensAre128BitHex) {
    SeededRandom random(42);
    std::set<std::string> seen;
    for (int i = 0; i < 1000; ++i) {
        const std::string token = make_resume_token(random);
        EXPECT_TRUE(proto::is_resume_token(token)) << token;
        seen.insert(token);
    }
    EXPECT_EQ(seen.size(), 1000U);
}

TEST(Random, SeededSequencesRepeat) {
    SeededRandom a(7);
    SeededRandom b(7);
    EXPECT_EQ(make_resume_token(a), make_resume_token(b));
    EXPECT_EQ(make_room_code(a), make_room_code(b));
}

TEST(Random, RoomCodesUseTheAlphabetEvenly) {
    SeededRandom random(3);
    std::map<char, int> counts;
    for (int i = 0; i < 3000; ++i) {
        const std::string code = make_room_code(random);
        ASSERT_TRUE(proto::is_room_code(code)) << code;
        for (char c : code) {
            ++counts[c];
        }
    }
    EXPECT_EQ(counts.size(), 31U);
    for (const auto& [c, n] : counts) {
        EXPECT_GT(n, 450) << c; // expected 18000 / 31 = 580.6
        EXPECT_LT(n, 720) << c;
    }
}

TEST(Random, SystemTokensDiffer) {
    SystemRandom random;
    EXPECT_NE(make_resume_token(random), make_resume_token(random));
}

struct DummyRoom {
    std::string code;
};
using TestRegistry = Registry<DummyRoom, int>;

TEST(Registry, PlayersGetDistinctIdsAndTokens) {
    SeededRandom random(1);
    TestRegistry registry(random, 10);
    const auto a = registry.new_player();
    const auto b = registry.new_player();
    EXPECT_NE(a.player_id, b.player_id);
    EXPECT_NE(a.token, b.token);
    ASSERT_TRUE(registry.find_player(a.token));
    EXPECT_EQ(registry.find_player(a.token)->player_id, a.player_id);
    EXPECT_FALSE(registry.find_player(std::string(32, '0')));
    registry.forget_player(a.token);
    EXPECT_FALSE(registry.find_player(a.token));
}

TEST(Registry, RoomLimit) {
    SeededRandom random(1);
    TestRegistry registry(random, 2);
    auto make = [](const std::string& code) {
        return std::make_shared<DummyRoom>(DummyRoom{code});
    };
    auto r1 = registry.create_room(make);
    auto r2 = registry.create_room(make);
    ASSERT_TRUE(std::holds_alternative<std::shared_ptr<DummyRoom>>(r1));
    ASSERT_TRUE(std::holds_alternative<std::shared_ptr<DummyRoom>>(r2));
    const auto r3 = registry.create_room(make);
    ASSERT_TRUE(std::holds_alternative<proto::Error>(r3));
    EXPECT_EQ(std::get<proto::Error>(r3).code, "too_many_rooms");
    const std::string code = std::get<std::shared_ptr<DummyRoom>>(r1)->code;
    EXPECT_TRUE(proto::is_room_code(code));
    EXPECT_EQ(registry.find_room(code), std::get<std::shared_ptr<DummyRoom>>(r1));
    registry.remove_room(code);
    EXPECT_EQ(registry.find_room(code), nullptr);
    EXPECT_TRUE(std::holds_alternative<std::shared_ptr<DummyRoom>>(registry.create_room(make)));
}

TEST(Registry, RemovingARoomForgetsItsPlayers) {
    SeededRandom random(1);
    TestRegistry registry(random, 2);
    const auto a = registry.new_player();
    registry.set_player_room(a.token, "ABCDEF");
    ASSERT_EQ(registry.find_player(a.token)->room_code, "ABCDEF");
    registry.remove_room("ABCDEF");
    EXPECT_FALSE(registry.find_player(a.token));
}

TEST(Registry, ARestoredRoomKeepsItsCodeAndItsSeatsAreClaimedOnceByTokenKey) {
    SeededRandom random(1);
    TestRegistry registry(random, 1);
    auto make = [](const std::string& code) {
        return std::make_shared<DummyRoom>(DummyRoom{code});
    };
    ASSERT_TRUE(std::holds_alternative<std::shared_ptr<DummyRoom>>(registry.create_room(make)));
    // Restored rooms are not bound by the room limit; a code is taken once.
    const auto room = registry.add_room("QQQQQQ", make);
    ASSERT_NE(room, nullptr);
    EXPECT_EQ(room->code, "QQQQQQ");
    EXPECT_EQ(registry.add_room("QQQQQQ", make), nullptr);
    const std::int64_t id = registry.add_restored_seat("hash-of-t1", "QQQQQQ");
    EXPECT_NE(id, registry.new_player().player_id);
    EXPECT_FALSE(registry.claim_restored("t2", "hash-of-t2"));
    const auto claimed = registry.claim_restored("t1", "hash-of-t1");
    ASSERT_TRUE(claimed);
    EXPECT_EQ(claimed->player_id, id);
    EXPECT_EQ(claimed->token, "t1");
    EXPECT_EQ(claimed->room_code, "QQQQQQ");
    EXPECT_EQ(registry.find_player("t1")->player_id, id);
    EXPECT_FALSE(registry.claim_restored("t1", "hash-of-t1")); // once
    // Removing the room drops the claims nobody made.
    (void)registry.add_restored_seat("hash-of-t3", "QQQQQQ");
    registry.remove_room("QQQQQQ");
    EXPECT_FALSE(registry.claim_restored("t3", "hash-of-t3"));
}

TEST(Registry, QuickMatchPairsWithinARuleSet) {
    SeededRandom random(1);
    TestRegistry registry(random, 2);
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 2, 1, 100));
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 2, 1, 100)); // not queued twice
    EXPECT_EQ(registry.waiting_count(), 1U);
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Seed, 2, 2, 200)); // another rule set
    const auto partner = registry.quick_match(proto::RuleSet::Icf, 2, 3, 300);
    ASSERT_TRUE(partner);
    EXPECT_EQ(*partner, (std::vector<int>{100}));
    EXPECT_EQ(registry.waiting_count(), 1U);
    EXPECT_TRUE(registry.cancel_quick_match(2)); // it was waiting
    EXPECT_EQ(registry.waiting_count(), 0U);
    EXPECT_FALSE(registry.cancel_quick_match(2)); // no longer
    EXPECT_FALSE(registry.cancel_quick_match(1)); // paired: taken out by the partner
}

TEST(Registry, QuickMatchForDoublesGroupsFourOfTheSameRuleSetAndSeatCount) {
    SeededRandom random(1);
    TestRegistry registry(random, 2);
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 4, 1, 100));
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 2, 5, 500));  // singles: apart
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Seed, 4, 6, 600)); // another rule set
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 4, 2, 200));
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 4, 2, 200)); // not queued twice
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 4, 3, 300));
    EXPECT_EQ(registry.waiting_count(), 5U);
    const auto group = registry.quick_match(proto::RuleSet::Icf, 4, 4, 400);
    ASSERT_TRUE(group);
    EXPECT_EQ(*group, (std::vector<int>{100, 200, 300})); // longest-waiting first
    EXPECT_EQ(registry.waiting_count(), 2U);
    EXPECT_FALSE(registry.cancel_quick_match(2));
    EXPECT_TRUE(registry.cancel_quick_match(5));
}

TEST(Registry, AWaitThatRunsOutTakesTheWholeQueueOfItsMode) {
    SeededRandom random(1);
    TestRegistry registry(random, 2);
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 4, 1, 100));
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 4, 2, 200));
    EXPECT_FALSE(registry.quick_match(proto::RuleSet::Icf, 2, 3, 300));
    EXPECT_FALSE(registry.take_waiting(proto::RuleSet::Icf, 4, 3)); // waits for singles
    const auto others = registry.take_waiting(proto::RuleSet::Icf, 4, 1);
    ASSERT_TRUE(others);
    EXPECT_EQ(*others, (std::vector<int>{200}));
    EXPECT_FALSE(registry.take_waiting(proto::RuleSet::Icf, 4, 2)); // taken along
    EXPECT_EQ(registry.waiting_count(), 1U);
    const auto alone = registry.take_waiting(proto::RuleSet::Icf, 2, 3);
    ASSERT_TRUE(alone);
    EXPECT_TRUE(alone->empty());
    EXPECT_EQ(registry.waiting_count(), 0U);
}

TEST(Metrics, PrometheusText) {
    Metrics m;
    m.connections = 3;
    m.rooms = 2;
    m.bytes_out_total = 1234;
    m.observe_snapshot_lag_ms(0.2);
    m.observe_snapshot_lag_ms(3.0);
    m.observe_snapshot_lag_ms(500.0);
    const std::string text = m.prometheus_text();
    EXPECT_NE(text.find("# TYPE carrom_connections gauge\ncarrom_connections 3\n"),
              std::string::npos);
    EXPECT_NE(text.find("carrom_rooms 2\n"), std::string::npos);
    EXPECT_NE(text.find("carrom_bytes_out_total 1234\n"), std::string::npos);
    EXPECT_NE(text.find("carrom_snapshot_lag_seconds_bucket{le=\"0.0005\"} 1\n"),
              std::string::npos);
    EXPECT_NE(text.find("carrom_snapshot_lag_seconds_bucket{le=\"0.005\"} 2\n"), std::string::npos);
    EXPECT_NE(text.find("carrom_snapshot_lag_seconds_bucket{le=\"+Inf\"} 3\n"), std::string::npos);
    EXPECT_NE(text.find("carrom_snapshot_lag_seconds_sum 0.503200\n"), std::string::npos);
    EXPECT_NE(text.find("carrom_snapshot_lag_seconds_count 3\n"), std::string::npos);
}

} // namespace
} // namespace carrom::server
