#include "carrom/client/coins_left.hpp"
#include "carrom/client/plain_words.hpp"

#include <gtest/gtest.h>

namespace carrom::client {
namespace {

RenderedBody piece(int id, BodyKind kind, bool falling = false) {
    RenderedBody b;
    b.id = id;
    b.kind = kind;
    b.falling = falling;
    return b;
}

TEST(CoinsLeft, CountsTheDrawnCoinsButNotFallingOnesOrTheStriker) {
    const std::vector<RenderedBody> drawn = {
        piece(0, BodyKind::Queen),       piece(1, BodyKind::Black),
        piece(2, BodyKind::White),       piece(3, BodyKind::White),
        piece(4, BodyKind::Black, true), piece(5, BodyKind::White, true),
        piece(19, BodyKind::Striker),
    };
    EXPECT_EQ(count_coins(drawn), (CoinsOnBoard{2, 1, true}));
    EXPECT_EQ(count_coins({piece(0, BodyKind::Queen, true)}), (CoinsOnBoard{0, 0, false}));
    EXPECT_EQ(count_coins({}), (CoinsOnBoard{}));
}

TEST(CoinsLeft, IcfAndSeedCountTheSeatsColourAndTheQueen) {
    const CoinsOnBoard board{7, 4, true};
    for (proto::RuleSet rules : {proto::RuleSet::Icf, proto::RuleSet::Seed}) {
        EXPECT_EQ(seat_coins(board, rules, proto::Colour::White),
                  (SeatCoins{proto::Colour::White, 7, true}));
        EXPECT_EQ(seat_coins(board, rules, proto::Colour::Black),
                  (SeatCoins{proto::Colour::Black, 4, true}));
        EXPECT_EQ(seat_coins(board, rules, proto::Colour::None), std::nullopt);
    }
    EXPECT_EQ(seat_coins({7, 4, false}, proto::RuleSet::Icf, proto::Colour::Black),
              (SeatCoins{proto::Colour::Black, 4, false}));
}

TEST(CoinsLeft, FreestyleCountsEveryCoinForBothSeats) {
    const CoinsOnBoard board{5, 6, true};
    for (proto::Colour colour : {proto::Colour::None, proto::Colour::White}) {
        EXPECT_EQ(seat_coins(board, proto::RuleSet::Freestyle, colour),
                  (SeatCoins{proto::Colour::None, 11, true}));
    }
}

TEST(CoinsLeft, DiscPoolCountsOwnCoinsAndHasNoQueen) {
    // The queen is out of play in discpool; even a queen drawn by mistake is no target.
    const CoinsOnBoard board{9, 3, true};
    EXPECT_EQ(seat_coins(board, proto::RuleSet::DiscPool, proto::Colour::White),
              (SeatCoins{proto::Colour::White, 9, false}));
    EXPECT_EQ(seat_coins(board, proto::RuleSet::DiscPool, proto::Colour::Black),
              (SeatCoins{proto::Colour::Black, 3, false}));
}

TEST(CoinsLeft, SaidInPlainWords) {
    EXPECT_EQ(coins_left_text({proto::Colour::White, 7, true}), "7 white + queen left");
    EXPECT_EQ(coins_left_text({proto::Colour::Black, 1, false}), "1 black left");
    EXPECT_EQ(coins_left_text({proto::Colour::None, 12, true}), "12 coins + queen left");
    EXPECT_EQ(coins_left_text({proto::Colour::None, 1, false}), "1 coin left");
    EXPECT_EQ(coins_left_text({proto::Colour::White, 0, false}), "no white left");
    EXPECT_EQ(coins_left_text({proto::Colour::None, 0, false}), "no coins left");
    EXPECT_EQ(coins_left_text({proto::Colour::Black, 0, true}), "only the queen left");
}

} // namespace
} // namespace carrom::client
