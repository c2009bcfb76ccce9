// How a rating and its change are shown: "1520?", "1532 (+14)".
#include "carrom/ratings/rating.hpp"

#include <gtest/gtest.h>

namespace carrom::ratings {
namespace {

TEST(RatingLabel, ProvisionalFromTheThresholdOn) {
    EXPECT_FALSE(is_provisional(Rating{1500.0, 109.99, 0.06}));
    EXPECT_TRUE(is_provisional(Rating{1500.0, 110.0, 0.06}));
    EXPECT_TRUE(is_provisional(Rating{}));
}

TEST(RatingLabel, RoundsAndMarksProvisionalRatings) {
    EXPECT_EQ(rating_label(Rating{1519.6, 200.0, 0.06}), "1520?");
    EXPECT_EQ(rating_label(Rating{1687.4, 60.0, 0.06}), "1687");
    EXPECT_EQ(rating_label(Rating{}), "1500?");
}

TEST(RatingLabel, ChangeHasItsSign) {
    const Rating before{1518.4, 60.0, 0.06};
    EXPECT_EQ(rating_change_label(before, Rating{1532.2, 60.0, 0.06}), "+14");
    EXPECT_EQ(rating_change_label(before, Rating{1509.0, 60.0, 0.06}), "-9");
    EXPECT_EQ(rating_change_label(before, Rating{1518.3, 60.0, 0.06}), "+0");
}

} // namespace
} // namespace carrom::ratings
