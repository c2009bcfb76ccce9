// The server's bot names and the level read back from them (recovery after a restart).
#include "bot_seat_name.hpp"

#include <gtest/gtest.h>

namespace carrom::server {
namespace {

using proto::BotLevel;

TEST(BotSeatName, SinglesNamesTheLevelOnly) {
    EXPECT_EQ(bot_seat_name(BotLevel::Hard, 1, 2), "Bot (hard)");
    EXPECT_EQ(bot_seat_name(BotLevel::Easy, 1, 2), "Bot (easy)");
}

TEST(BotSeatName, DoublesGivesEachSeatItsOwnName) {
    EXPECT_EQ(bot_seat_name(BotLevel::Easy, 1, 4), "Bot Ravi (easy)");
    EXPECT_EQ(bot_seat_name(BotLevel::Easy, 2, 4), "Bot Kiran (easy)");
    EXPECT_EQ(bot_seat_name(BotLevel::Easy, 3, 4), "Bot Dev (easy)");
    EXPECT_EQ(bot_seat_name(BotLevel::Medium, 0, 4), "Bot Mira (medium)");
}

TEST(BotSeatName, LevelComesBackFromEveryNameTheServerGives) {
    for (const BotLevel level :
         {BotLevel::Random, BotLevel::Easy, BotLevel::Medium, BotLevel::Hard}) {
        for (int seat = 0; seat < 4; ++seat) {
            EXPECT_EQ(bot_level_of_name(bot_seat_name(level, seat, 4)), level) << seat;
        }
        EXPECT_EQ(bot_level_of_name(bot_seat_name(level, 1, 2)), level);
    }
}

TEST(BotSeatName, OtherNamesPlayMedium) {
    EXPECT_EQ(bot_level_of_name("Asha"), BotLevel::Medium);
    EXPECT_EQ(bot_level_of_name("Asha (hard)"), BotLevel::Medium);
    EXPECT_EQ(bot_level_of_name("Bot (expert)"), BotLevel::Medium);
    EXPECT_EQ(bot_level_of_name("Bot (hard"), BotLevel::Medium);
    EXPECT_EQ(bot_level_of_name("Bot"), BotLevel::Medium);
    EXPECT_EQ(bot_level_of_name("Bot ()"), BotLevel::Medium);
}

} // namespace
} // namespace carrom::server
