// net::Backoff: the delays double from 250 ms to the 5 s cap, each drawn in [d/2, d], and the
// tries stop once the seat's grace (plus margin) has passed since the loss.
#include "carrom/net/backoff.hpp"

#include <gtest/gtest.h>

namespace carrom::net {
namespace {

using namespace std::chrono_literals;

TEST(Backoff, DoublesWithJitterUpToTheCap) {
    Backoff backoff({}, 7);
    backoff.start(Backoff::Clock::now());
    const std::int64_t nominal[] = {250, 500, 1000, 2000, 4000, 5000, 5000, 5000};
    for (const std::int64_t d : nominal) {
        const auto delay = backoff.next_delay().count();
        EXPECT_GE(delay, d / 2);
        EXPECT_LE(delay, d);
    }
    EXPECT_EQ(backoff.tries(), 8);
}

TEST(Backoff, JitterSpreadsTheDelays) {
    Backoff a({}, 1);
    Backoff b({}, 2);
    bool differ = false;
    for (int i = 0; i < 8; ++i) {
        differ = differ || a.next_delay() != b.next_delay();
    }
    EXPECT_TRUE(differ);
}

TEST(Backoff, ExpiresAfterTheGivenTimeAndStartsAgain) {
    Backoff backoff({250ms, 5000ms, 3000ms}, 3);
    const auto t0 = Backoff::Clock::now();
    backoff.start(t0);
    backoff.next_delay();
    EXPECT_FALSE(backoff.expired(t0 + 2999ms));
    EXPECT_TRUE(backoff.expired(t0 + 3000ms));
    backoff.start(t0 + 10s);
    EXPECT_EQ(backoff.tries(), 0);
    EXPECT_FALSE(backoff.expired(t0 + 11s));
    EXPECT_LE(backoff.next_delay(), 250ms);
}

} // namespace
} // namespace carrom::net
