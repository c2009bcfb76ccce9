// TokenBucket (server/include/carrom/server/token_bucket.hpp): the one bucket of both rate
// limiters, exact token counts at the times passed in.
#include "carrom/server/token_bucket.hpp"

#include <gtest/gtest.h>

namespace carrom::server {
namespace {

TEST(TokenBucket, StartsFullAndTakesOneTokenPerCall) {
    TokenBucket bucket(10.0, 3.0, 1000); // 10 per second: one token per 100 ms
    EXPECT_TRUE(bucket.full(1000));
    EXPECT_DOUBLE_EQ(bucket.tokens(1000), 3.0);
    EXPECT_TRUE(bucket.take(1000));
    EXPECT_FALSE(bucket.full(1000));
    EXPECT_DOUBLE_EQ(bucket.tokens(1000), 2.0);
    EXPECT_TRUE(bucket.take(1000));
    EXPECT_TRUE(bucket.take(1000));
    EXPECT_DOUBLE_EQ(bucket.tokens(1000), 0.0);
    EXPECT_FALSE(bucket.take(1000));
    EXPECT_DOUBLE_EQ(bucket.tokens(1000), 0.0); // a refused take costs nothing
}

TEST(TokenBucket, EarnsTokensWithTimeUpToItsCapacity) {
    TokenBucket bucket(10.0, 2.0, 0);
    EXPECT_TRUE(bucket.take(0));
    EXPECT_TRUE(bucket.take(0));
    EXPECT_DOUBLE_EQ(bucket.tokens(50), 0.5);
    EXPECT_FALSE(bucket.take(99)); // 0.99 tokens
    EXPECT_TRUE(bucket.take(100));
    EXPECT_DOUBLE_EQ(bucket.tokens(100), 0.0);
    EXPECT_DOUBLE_EQ(bucket.tokens(250), 1.5);
    EXPECT_FALSE(bucket.full(250));
    EXPECT_TRUE(bucket.full(300));
    EXPECT_DOUBLE_EQ(bucket.tokens(60000), 2.0); // never beyond the capacity
}

TEST(TokenBucket, TokensAndFullChangeNothing) {
    TokenBucket bucket(1.0, 1.0, 0);
    EXPECT_TRUE(bucket.take(0));
    EXPECT_TRUE(bucket.full(5000)); // asked, not taken
    EXPECT_EQ(bucket.last_ms(), 0);
    EXPECT_DOUBLE_EQ(bucket.tokens(500), 0.5);
}

TEST(TokenBucket, AnEarlierTimeEarnsNothingAndKeepsTheLatest) {
    TokenBucket bucket(1.0, 2.0, 1000);
    EXPECT_TRUE(bucket.take(1000));
    EXPECT_TRUE(bucket.take(1000));
    EXPECT_FALSE(bucket.take(400)); // a clock that went back: no token, time stays at 1000
    EXPECT_EQ(bucket.last_ms(), 1000);
    EXPECT_DOUBLE_EQ(bucket.tokens(400), 0.0);
    EXPECT_DOUBLE_EQ(bucket.tokens(1500), 0.5);
    EXPECT_FALSE(bucket.take(1500));
    EXPECT_EQ(bucket.last_ms(), 1500); // a refused take still moves the time on
}

TEST(TokenBucket, MillisecondsUntilTheNextToken) {
    TokenBucket bucket(4.0, 1.0, 0); // one token per 250 ms
    EXPECT_DOUBLE_EQ(bucket.ms_until_token(0), 0.0);
    EXPECT_TRUE(bucket.take(0));
    EXPECT_DOUBLE_EQ(bucket.ms_until_token(0), 250.0);
    EXPECT_DOUBLE_EQ(bucket.ms_until_token(100), 150.0);
    EXPECT_DOUBLE_EQ(bucket.ms_until_token(250), 0.0);
    EXPECT_DOUBLE_EQ(bucket.ms_until_token(900), 0.0);
}

} // namespace
} // namespace carrom::server
