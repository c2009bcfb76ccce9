// ResultHash: FNV-1a over the bits of a run's report. Small exact cases: the empty report, and
// changes that must (and must not) change the hash.

#include "carrom/result_hash.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace carrom {
namespace {

std::uint64_t hash_of(const SimResult& result) {
    ResultHash hash;
    hash.add(result);
    return hash.value();
}

// An empty report hashes only its end time, 0.0: eight zero bytes.
TEST(ResultHash, AnEmptyReportHashesEightZeroBytes) {
    EXPECT_EQ(hash_of(SimResult{}), 0x47fe0d7eaf8e51e3ULL);
}

// The exact value was checked with an independent FNV-1a over the same words: the event's time,
// kind, ids, impulse and position; the body's position, velocity and pocketed flag; the end
// time; the pocket order.
TEST(ResultHash, TheSameReportGivesTheSameHash) {
    SimResult result;
    result.events.push_back({0.25, EventKind::Collision, 19, 4, 12.5, {300.0, 320.0}});
    result.bodies.push_back(Body{});
    result.pocket_order = {3, 7};
    const SimResult copy = result;
    EXPECT_EQ(hash_of(result), hash_of(copy));
    EXPECT_EQ(hash_of(result), 0x1c568705c90c573eULL);
}

TEST(ResultHash, NegativeZeroDiffersFromZero) {
    SimResult negative_zero;
    negative_zero.end_time_s = -0.0;
    EXPECT_NE(hash_of(negative_zero), hash_of(SimResult{}));
}

TEST(ResultHash, TheLastBitOfAnEventTimeCounts) {
    SimResult a;
    a.events.push_back({0.25, EventKind::Cushion, 2, 1, 3.0, {35.0, 100.0}});
    SimResult b = a;
    b.events[0].t_s = std::nextafter(0.25, 1.0);
    EXPECT_NE(hash_of(a), hash_of(b));
}

TEST(ResultHash, ThePocketOrderCounts) {
    SimResult a;
    a.pocket_order = {3, 7};
    SimResult b;
    b.pocket_order = {7, 3};
    EXPECT_NE(hash_of(a), hash_of(b));
}

TEST(ResultHash, RunsAddedInTurnHashTheirSequence) {
    SimResult first;
    first.end_time_s = 1.0;
    SimResult second;
    second.end_time_s = 2.0;
    ResultHash forward;
    forward.add(first);
    forward.add(second);
    ResultHash backward;
    backward.add(second);
    backward.add(first);
    EXPECT_NE(forward.value(), backward.value());
    EXPECT_NE(forward.value(), hash_of(first));
}

} // namespace
} // namespace carrom
