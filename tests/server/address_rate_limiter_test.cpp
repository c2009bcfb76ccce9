// AddressRateLimiter (server/src/address_rate_limiter.hpp): a token bucket per address, the
// Retry-After seconds of a refusal, and the bounded table.
#include "address_rate_limiter.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace carrom::server {
namespace {

TEST(AddressRateLimiter, ABurstThenOneRequestPerTokenAndTheSecondsToWait) {
    AddressRateLimiter limiter(2.0, 3.0, 16); // 2 per second, bursts of 3
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(limiter.take("10.0.0.1", 1000), 0) << i;
    }
    EXPECT_EQ(limiter.take("10.0.0.1", 1000), 1); // one token in 500 ms: retry in 1 s
    EXPECT_EQ(limiter.take("10.0.0.2", 1000), 0); // another address has its own bucket
    EXPECT_EQ(limiter.take("10.0.0.1", 1499), 1);
    EXPECT_EQ(limiter.take("10.0.0.1", 1600), 0); // refilled one token
    EXPECT_EQ(limiter.take("10.0.0.1", 1600), 1);
    EXPECT_EQ(limiter.take("10.0.0.1", 60000), 0); // refills to the burst, not beyond
    EXPECT_EQ(limiter.take("10.0.0.1", 60000), 0);
    EXPECT_EQ(limiter.take("10.0.0.1", 60000), 0);
    EXPECT_EQ(limiter.take("10.0.0.1", 60000), 1);
}

TEST(AddressRateLimiter, ASlowRateWaitsWholeSeconds) {
    AddressRateLimiter limiter(0.25, 1.0, 16); // one request per 4 s
    EXPECT_EQ(limiter.take("a", 0), 0);
    EXPECT_EQ(limiter.take("a", 0), 4);
    EXPECT_EQ(limiter.take("a", 1000), 3);
    EXPECT_EQ(limiter.take("a", 3900), 1);
}

TEST(AddressRateLimiter, TheTableStaysBoundedIdleAddressesGoFirst) {
    AddressRateLimiter limiter(1.0, 2.0, 3);
    EXPECT_EQ(limiter.take("busy", 0), 0);
    EXPECT_EQ(limiter.take("busy", 0), 0);
    EXPECT_EQ(limiter.take("idle1", 0), 0);
    EXPECT_EQ(limiter.take("idle2", 0), 0);
    EXPECT_EQ(limiter.size(), 3U);
    // At 1.5 s idle1 and idle2 have refilled (forgetting them changes nothing); busy has not.
    EXPECT_EQ(limiter.take("new", 1500), 0);
    EXPECT_EQ(limiter.size(), 2U);
    EXPECT_EQ(limiter.take("busy", 1500), 0);
    EXPECT_EQ(limiter.take("busy", 1500), 1); // still limited: it was kept
    // A full table of active addresses: the least recently used one goes.
    for (int i = 0; i < 100; ++i) {
        EXPECT_EQ(limiter.take("flood" + std::to_string(i), 1500), 0);
        EXPECT_LE(limiter.size(), 3U);
    }
}

TEST(AddressRateLimiter, AFullTableOfActiveAddressesForgetsTheLeastRecentlySeen) {
    AddressRateLimiter limiter(1.0, 2.0, 3); // 1 per second, bursts of 2
    const std::vector<std::pair<std::string, std::int64_t>> seen = {
        {"a", 0}, {"b", 100}, {"c", 200}};
    for (const auto& [address, ms] : seen) {
        EXPECT_EQ(limiter.take(address, ms), 0);
        EXPECT_EQ(limiter.take(address, ms), 0); // empty: not idle
    }
    EXPECT_EQ(limiter.take("d", 300), 0); // no bucket has refilled: "a" (seen at 0) goes
    EXPECT_EQ(limiter.size(), 3U);
    EXPECT_EQ(limiter.take("c", 300), 1); // still limited: kept
    EXPECT_EQ(limiter.take("b", 300), 1); // still limited: kept
    EXPECT_EQ(limiter.take("a", 300), 0); // forgotten: a new, full bucket (0.3 tokens if kept)
}

} // namespace
} // namespace carrom::server
