// Identified players and ratings in the store, on each backend: the update is written with the
// result, once per match and player, also after a reopen; unrated matches change nothing; the
// leaderboard.
#include "carrom/ratings/glicko2.hpp"
#include "store/rating_update.hpp"
#include "store/store_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

namespace carrom::store::test {
namespace {

IdentifiedPlayer player_named(const std::string& name) {
    return IdentifiedPlayer{hash_token("key of " + name), name, name, 1000};
}

// An entry ending the game: seat `loser` forfeits (a timeout loss and a resignation are
// forfeits too), or a draw when loser is negative.
proto::JournalEntry game_end_entry(int loser, std::int64_t time_ms) {
    proto::ForfeitEntry forfeit;
    forfeit.seat = std::max(loser, 0);
    rules::GameResult result;
    if (loser >= 0) {
        result.winner_team = 1 - loser;
    }
    result.reason = rules::RuleCode::Forfeit;
    forfeit.outcome.game_end = result;
    forfeit.outcome.scores = {0, 0};
    return proto::JournalEntry{time_ms, forfeit};
}

// A match between two identified players (seats 0 and 1), rated unless told otherwise.
void rated_match(MatchStore& store, const std::string& id, const IdentifiedPlayer& first,
                 const IdentifiedPlayer& second, int loser, std::int64_t time_ms = 5000) {
    store.create(created(id, first.name, second.name));
    store.set_rated_seat(id, 0, first.key_hash);
    store.set_rated_seat(id, 1, second.key_hash);
    store.append(id, 0, game_end_entry(loser, time_ms));
}

// Two identified players, Ann and Bea, on a new store of each backend.
class StoreRatings : public StoreTest {
protected:
    std::unique_ptr<MatchStore> open_with_ann_and_bea() {
        auto store = open();
        store->save_player(ann);
        store->save_player(bea);
        return store;
    }
    const IdentifiedPlayer ann = player_named("Ann");
    const IdentifiedPlayer bea = player_named("Bea");
};
CARROM_STORE_BACKENDS(StoreRatings);

PlayerRating only_rating(MatchStore& store, const IdentifiedPlayer& player) {
    auto loaded = store.player_ratings(player.key_hash);
    EXPECT_TRUE(loaded.ok());
    EXPECT_EQ(loaded.value.size(), 1U);
    return loaded.value.empty() ? PlayerRating{} : loaded.value[0];
}

TEST_P(StoreRatings, PlayersAreKeptByKeyHashWithTheirLatestName) {
    auto store = open_with_ann_and_bea();
    IdentifiedPlayer renamed = ann;
    renamed.name = "Annie";
    renamed.name_key = "annie";
    store->save_player(renamed);
    ASSERT_TRUE(store->flush(kFlush));
    const auto players = store->load_players();
    ASSERT_TRUE(players.ok());
    ASSERT_EQ(players.value.size(), 2U);
    EXPECT_TRUE(std::find(players.value.begin(), players.value.end(), renamed) !=
                players.value.end());
}

TEST_P(StoreRatings, TwoKeysCannotHoldOneNameKey) {
    auto store = open();
    store->save_player(player_named("Ann"));
    IdentifiedPlayer impostor = player_named("Other");
    impostor.name_key = "Ann";
    store->save_player(impostor);
    ASSERT_TRUE(store->flush(kFlush));
    EXPECT_EQ(store->health().dropped_total, 1U);
    EXPECT_EQ(store->load_players().value.size(), 1U);
}

TEST_P(StoreRatings, ARatedResultUpdatesBothPlayersAsGlicko2Says) {
    auto store = open_with_ann_and_bea();
    rated_match(*store, "m1", ann, bea, 0); // Ann forfeits: Bea wins
    ASSERT_TRUE(store->flush(kFlush));
    const PlayerRating a = only_rating(*store, ann);
    const PlayerRating b = only_rating(*store, bea);
    const auto expected = rate_singles_game(
        {RatedSeat{ann.key_hash, std::nullopt}, RatedSeat{bea.key_hash, std::nullopt}},
        rules::RuleSet::Icf, rules::GameResult{1}, 5000);
    EXPECT_EQ(a, expected[0].after);
    EXPECT_EQ(b, expected[1].after);
    EXPECT_NEAR(b.rating.rating, 1662.3, 0.1);
    EXPECT_NEAR(a.rating.rating, 1337.7, 0.1);
    EXPECT_EQ(a.games, 1);
    EXPECT_EQ(a.losses, 1);
    EXPECT_EQ(b.wins, 1);
    EXPECT_EQ(b.last_game_ms, 5000);
}

TEST_P(StoreRatings, AResultIsAppliedOnceAlsoWhenItsEndComesAgainAfterAReopen) {
    PlayerRating after_first;
    {
        auto store = open_with_ann_and_bea();
        rated_match(*store, "m1", ann, bea, 1);
        store->append("m1", 1, game_end_entry(0, 6000)); // a second end of the same match
        ASSERT_TRUE(store->flush(kFlush));
        after_first = only_rating(*store, ann);
        EXPECT_EQ(after_first.games, 1);
        EXPECT_EQ(after_first.wins, 1);
    }
    auto store = open();
    EXPECT_EQ(only_rating(*store, ann), after_first);
    store->append("m1", 2, game_end_entry(0, 7000));
    ASSERT_TRUE(store->flush(kFlush));
    EXPECT_EQ(only_rating(*store, ann), after_first);
}

TEST_P(StoreRatings, MatchesWithoutTwoDifferentRatedPlayersChangeNoRating) {
    auto store = open_with_ann_and_bea();
    store->create(created("one_seat", "Ann", "Bot (medium)")); // a bot seat is never rated
    store->set_rated_seat("one_seat", 0, ann.key_hash);
    store->append("one_seat", 0, game_end_entry(1, 5000));
    rated_match(*store, "self", ann, ann, 1); // one key in both seats
    store->create(created("unrated", "Ann", "Bea"));
    store->append("unrated", 0, game_end_entry(1, 5000));
    ASSERT_TRUE(store->flush(kFlush));
    EXPECT_TRUE(store->player_ratings(ann.key_hash).value.empty());
    EXPECT_TRUE(store->player_ratings(bea.key_hash).value.empty());
}

TEST_P(StoreRatings, AMatchCutOffAndNeverFinishedIsNotRated) {
    auto store = open_with_ann_and_bea();
    store->create(created("cut", "Ann", "Bea"));
    store->set_rated_seat("cut", 0, ann.key_hash);
    store->set_rated_seat("cut", 1, bea.key_hash);
    store->mark_finished("cut", 9000);
    ASSERT_TRUE(store->flush(kFlush));
    EXPECT_TRUE(store->player_ratings(ann.key_hash).value.empty());
}

TEST_P(StoreRatings, AnUnfinishedMatchWithRatedSeatsIsRecoveredAsRated) {
    {
        auto store = open_with_ann_and_bea();
        store->create(created("rated_open", "Ann", "Bea"));
        store->set_rated_seat("rated_open", 0, ann.key_hash);
        store->set_rated_seat("rated_open", 1, bea.key_hash);
        store->create(created("unrated_open", "Ann", "Bea"));
        ASSERT_TRUE(store->flush(kFlush));
    }
    auto store = open();
    const auto loaded = store->load_unfinished();
    ASSERT_TRUE(loaded.ok());
    ASSERT_EQ(loaded.value.size(), 2U);
    for (const RecoveredMatch& match : loaded.value) {
        EXPECT_EQ(match.rated, match.id == "rated_open") << match.id;
    }
}

TEST_P(StoreRatings, DaysAwayAgeBothRatingsBeforeTheNextGame) {
    auto store = open_with_ann_and_bea();
    rated_match(*store, "m1", ann, bea, 1, 0);
    ASSERT_TRUE(store->flush(kFlush));
    const std::array<RatedSeat, 2> before{RatedSeat{ann.key_hash, only_rating(*store, ann)},
                                          RatedSeat{bea.key_hash, only_rating(*store, bea)}};
    const std::int64_t later = 30 * kRatingPeriodMs + 5;
    rated_match(*store, "m2", ann, bea, 1, later);
    ASSERT_TRUE(store->flush(kFlush));
    const auto expected =
        rate_singles_game(before, rules::RuleSet::Icf, rules::GameResult{0}, later);
    EXPECT_EQ(expected[0].before, ratings::Glicko2{}.age(before[0].stored->rating, 30));
    EXPECT_EQ(only_rating(*store, ann), expected[0].after);
    EXPECT_EQ(only_rating(*store, bea), expected[1].after);
    EXPECT_EQ(only_rating(*store, ann).games, 2);
}

TEST_P(StoreRatings, LeaderboardListsEstablishedRatingsBestFirst) {
    auto store = open();
    const std::array<IdentifiedPlayer, 4> p{player_named("Ann"), player_named("Bea"),
                                            player_named("Cy"), player_named("Dev")};
    for (const auto& player : p) {
        store->save_player(player);
    }
    // Ann and Bea play 25 games, Ann winning every other one from the first: both established. Cy
    // beats Dev once: provisional.
    for (int game = 0; game < 25; ++game) {
        rated_match(*store, "ab" + std::to_string(game), p[0], p[1], game % 2 == 0 ? 1 : 0,
                    1000 + game);
    }
    rated_match(*store, "cd", p[2], p[3], 1, 2000);
    ASSERT_TRUE(store->flush(kFlush));
    const auto board = store->leaderboard(rules::RuleSet::Icf, 50);
    ASSERT_TRUE(board.ok());
    ASSERT_EQ(board.value.size(), 2U);
    EXPECT_EQ(board.value[0].name, "Ann");
    EXPECT_EQ(board.value[1].name, "Bea");
    EXPECT_GT(board.value[0].rating.rating.rating, board.value[1].rating.rating.rating);
    EXPECT_FALSE(ratings::is_provisional(board.value[1].rating.rating));
    EXPECT_TRUE(ratings::is_provisional(only_rating(*store, p[2]).rating));
    EXPECT_EQ(store->leaderboard(rules::RuleSet::Icf, 1).value.size(), 1U);
    EXPECT_TRUE(store->leaderboard(rules::RuleSet::Freestyle, 50).value.empty());
}

} // namespace
} // namespace carrom::store::test
