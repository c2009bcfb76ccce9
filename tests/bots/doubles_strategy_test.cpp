// The strategies in doubles: four seats (bottom, right, top, left; partners opposite), each
// placing the striker along its own baseline, shooting into the board from its side, and
// treating its team's colour (the partner's coins) as its own.
#include "bots/search_support.hpp"
#include "carrom/bots/arena.hpp"
#include "carrom/bots/greedy_strategy.hpp"
#include "carrom/bots/position_value.hpp"
#include "carrom/bots/random_strategy.hpp"
#include "carrom/bots/shot_candidates.hpp"
#include "carrom/bots/shot_geometry.hpp"
#include "carrom/bots/stroke_evaluator.hpp"
#include "carrom/rules/match.hpp"
#include "carrom/rules/placement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace carrom::bots {
namespace {

using test::candidates;
using test::play;

constexpr double kPi = std::numbers::pi;

rules::MatchState doubles(rules::RuleSet rule_set) {
    rules::RulesConfig config;
    config.seat_count = 4;
    config.shot_clock_s = 0.0;
    return rules::new_match(rule_set, config, PhysicsConfig{});
}

rules::Side side_of(const rules::MatchState& state, int seat) {
    return state.seats[static_cast<std::size_t>(seat)].side;
}

// A point of a scene laid out for the bottom seat, moved so that the seat on `side` sees the
// same scene: the bottom baseline lands on side's baseline and a striker position along the
// baseline stays the same number (the top seat: mirrored top to bottom; right: mirrored about
// the diagonal; left: a quarter turn). The board and its pockets map onto themselves.
Vec2 seen_from(rules::Side side, Vec2 p, double board_px = 600.0) {
    switch (side) {
    case rules::Side::Bottom:
        return p;
    case rules::Side::Top:
        return {p.x, board_px - p.y};
    case rules::Side::Right:
        return {p.y, p.x};
    case rules::Side::Left:
        return {board_px - p.y, p.x};
    }
    return p;
}

int nth_of(const rules::MatchState& state, BodyKind kind, int n) {
    for (const Body& body : state.bodies) {
        if (body.kind == kind && n-- == 0) {
            return body.id;
        }
    }
    return -1;
}

// A board after the break with only the listed pieces on it (the queen covered earlier by
// seat 1 unless kept), at the listed positions.
rules::MatchState sparse(rules::MatchState state, const std::vector<std::pair<int, Vec2>>& keep) {
    state.break_done = true;
    state.strokes_this_board = 1;
    for (Body& body : state.bodies) {
        const bool kept = std::any_of(keep.begin(), keep.end(),
                                      [&](const auto& k) { return k.first == body.id; });
        if (!kept) {
            body.pocketed = true;
            state.pocketed.push_back(rules::PocketedPiece{body.id, body.kind, 1, 0});
        }
    }
    for (const auto& [id, pos] : keep) {
        state.bodies[static_cast<std::size_t>(id)].pos_px = pos;
    }
    const bool queen_kept =
        std::any_of(keep.begin(), keep.end(), [](const auto& k) { return k.first == kQueenId; });
    if (!queen_kept) {
        state.queen = {rules::QueenStatus::Covered, 1};
    }
    return state;
}

BodyKind own_colour(const rules::MatchState& state, int seat) {
    return rules::team_colour(state, rules::team_of(state, seat)).value_or(BodyKind::White);
}

TEST(DoublesGeometry, ForwardPointsIntoTheBoardFromEverySide) {
    const rules::MatchState state = doubles(rules::RuleSet::Icf);
    EXPECT_DOUBLE_EQ(forward_angle(state, 0), -kPi / 2.0); // bottom: up the screen
    EXPECT_DOUBLE_EQ(forward_angle(state, 1), kPi);        // right: towards -x
    EXPECT_DOUBLE_EQ(forward_angle(state, 2), kPi / 2.0);  // top: down the screen
    EXPECT_DOUBLE_EQ(forward_angle(state, 3), 0.0);        // left: towards +x
    const Vec2 centre = state.physics.centre();
    for (int seat = 0; seat < 4; ++seat) {
        const Vec2 striker =
            rules::striker_for(state.physics, side_of(state, seat), Shot{200.0, 0.0, 0.0}).pos_px;
        const double a = forward_angle(state, seat);
        const Vec2 ahead = striker + Vec2{std::cos(a), std::sin(a)} * 220.0;
        EXPECT_LT(length(ahead - centre), length(striker - centre) - 100.0) << "seat " << seat;
    }
}

TEST(DoublesGeometry, BaselinePositionsOfASideSeatAvoidACoinOnItsBaseline) {
    rules::MatchState state = doubles(rules::RuleSet::Freestyle);
    const int coin = nth_of(state, BodyKind::Black, 0);
    for (const int seat : {1, 3}) {
        const rules::Side side = side_of(state, seat);
        const rules::MatchState board = sparse(state, {{coin, seen_from(side, {300.0, 520.0})}});
        const StrokeEvaluator evaluator(board, seat);
        EXPECT_FALSE(evaluator.placement_legal(300.0));
        const std::vector<double> xs = legal_baseline_xs(evaluator, 9);
        ASSERT_GE(xs.size(), 8u);
        for (const double x : xs) {
            EXPECT_TRUE(shot_is_legal(board, seat, Shot{x, forward_angle(board, seat), 1.0}));
            EXPECT_GE(std::abs(x - 300.0), 32.0 - 1e-9) << "seat " << seat;
        }
        EXPECT_GE(std::abs(*nearest_legal_x(board, seat, 300.0) - 300.0), 32.0 - 1e-9);
    }
}

TEST(DoublesRandom, ShotsAreLegalAndAimedIntoTheBoardFromEverySeat) {
    for (int seat = 0; seat < 4; ++seat) {
        rules::MatchState state = doubles(rules::RuleSet::Icf);
        state.turn_seat = seat;
        RandomStrategy strategy(17);
        ExactEngine engine(state.physics);
        for (int i = 0; i < 100; ++i) {
            const Shot shot = strategy.choose_shot(state, seat, DecisionBudget{});
            EXPECT_TRUE(shot_is_legal(state, seat, shot));
            EXPECT_LE(std::abs(shot.angle_rad - forward_angle(state, seat)),
                      75.0 * kPi / 180.0 + 1e-12);
        }
        const auto result =
            rules::play_shot(state, seat, strategy.choose_shot(state, seat, {}), engine);
        EXPECT_FALSE(result.error) << "seat " << seat;
    }
}

TEST(DoublesValue, TheTeamsColourIsWantedByBothPartners) {
    // icf: seat 0 breaks, so seats 0 and 2 play white, 1 and 3 black.
    const rules::MatchState state = doubles(rules::RuleSet::Icf);
    const Body& white = state.bodies[static_cast<std::size_t>(nth_of(state, BodyKind::White, 0))];
    const Body& black = state.bodies[static_cast<std::size_t>(nth_of(state, BodyKind::Black, 0))];
    for (int seat = 0; seat < 4; ++seat) {
        const int team = rules::team_of(state, seat);
        EXPECT_EQ(wants_to_pocket(state, team, white), seat % 2 == 0) << "seat " << seat;
        EXPECT_EQ(wants_to_pocket(state, team, black), seat % 2 == 1) << "seat " << seat;
    }
    rules::MatchState after = state;
    after.bodies[static_cast<std::size_t>(white.id)].pocketed = true;
    const ValueWeights w;
    EXPECT_DOUBLE_EQ(position_value(after, rules::team_of(after, 2)), w.own_coin);
    EXPECT_DOUBLE_EQ(position_value(after, rules::team_of(after, 3)), -w.opponent_coin);
}

TEST(DoublesCandidates, AnAimedShotFromEverySidePocketsALoneCoin) {
    // The bottom seat's scene of ShotCandidates.AnAimedShotPocketsALoneCoinWhenPlayedExactly,
    // turned to each side: an own coin in the shooter's lower left, an opponent coin away.
    for (int seat = 0; seat < 4; ++seat) {
        const rules::MatchState base = doubles(rules::RuleSet::Icf);
        const rules::Side side = side_of(base, seat);
        const BodyKind own = own_colour(base, seat);
        const BodyKind theirs = own == BodyKind::White ? BodyKind::Black : BodyKind::White;
        const int mine = nth_of(base, own, 0);
        rules::MatchState state =
            sparse(base, {{mine, seen_from(side, {160.0, 380.0})},
                          {nth_of(base, own, 1), seen_from(side, {470.0, 120.0})},
                          {nth_of(base, theirs, 0), seen_from(side, {420.0, 200.0})}});
        state.turn_seat = seat;
        const StrokeEvaluator evaluator(state, seat);
        const std::vector<Shot> shots =
            aimed_shots(state, seat, legal_baseline_xs(evaluator, 9), AimSpec{});
        ASSERT_FALSE(shots.empty()) << "seat " << seat;
        int pocketed_mine = 0;
        for (const Shot& shot : shots) {
            const auto result = play(state, seat, shot);
            ASSERT_FALSE(result.error) << "seat " << seat;
            pocketed_mine += static_cast<int>(
                std::count(result.outcome.pocketed.begin(), result.outcome.pocketed.end(), mine));
        }
        EXPECT_GT(pocketed_mine, 0) << "seat " << seat;
    }
}

TEST(DoublesGreedy, FromEverySeatPocketsItsTeamsColourAndNotTheOpponents) {
    // icf, seat 0 broke: whites are team 0's (seats 0 and 2), blacks team 1's (seats 1 and 3).
    // The scene, turned to the shooter's side, is symmetric about the shooter's axis: a white
    // and a black each at the same distance from a pocket, so only the colour tells them apart.
    for (int seat = 0; seat < 4; ++seat) {
        const rules::MatchState base = doubles(rules::RuleSet::Icf);
        const rules::Side side = side_of(base, seat);
        const int w0 = nth_of(base, BodyKind::White, 0);
        const int w1 = nth_of(base, BodyKind::White, 1);
        const int b0 = nth_of(base, BodyKind::Black, 0);
        const int b1 = nth_of(base, BodyKind::Black, 1);
        rules::MatchState state = sparse(base, {{w0, seen_from(side, {230.0, 330.0})},
                                                {b0, seen_from(side, {370.0, 330.0})},
                                                {w1, seen_from(side, {130.0, 120.0})},
                                                {b1, seen_from(side, {470.0, 120.0})}});
        state.turn_seat = seat;
        GreedyOptions options;
        options.level = SkillLevel::Perfect;
        GreedyStrategy bot(options);
        const Shot shot = bot.choose_shot(state, seat, candidates(3000));
        EXPECT_TRUE(shot_is_legal(state, seat, shot)) << "seat " << seat;
        const auto result = play(state, seat, shot);
        ASSERT_FALSE(result.error) << "seat " << seat;
        EXPECT_TRUE(result.outcome.fouls.empty()) << "seat " << seat;
        const BodyKind own = own_colour(state, seat);
        EXPECT_EQ(own, seat % 2 == 0 ? BodyKind::White : BodyKind::Black);
        ASSERT_FALSE(result.outcome.pocketed.empty()) << "seat " << seat;
        for (const int id : result.outcome.pocketed) {
            EXPECT_EQ(state.bodies[static_cast<std::size_t>(id)].kind, own)
                << "seat " << seat << " pocketed piece " << id;
        }
    }
}

TEST(DoublesArena, AGreedyTeamBeatsARandomTeamAndEverySeatPlays) {
    rules::RulesConfig config;
    config.seat_count = 4;
    config.shot_clock_s = 0.0;
    config.target_points = 3; // one board decides it
    const rules::MatchState start = rules::new_match(rules::RuleSet::Icf, config, PhysicsConfig{});
    // Five seeded games: one game is luck (a random team's lucky break can win a board), the
    // majority is skill.
    int greedy_wins = 0;
    for (std::uint64_t game = 0; game < 5; ++game) {
        RandomStrategy r0(1 + 10 * game);
        RandomStrategy r2(2 + 10 * game);
        GreedyOptions options; // easy: it misses now and then, so the turn goes round
        options.level = SkillLevel::Easy;
        options.seed = 3 + 10 * game;
        GreedyStrategy g1(options);
        options.seed = 4 + 10 * game;
        GreedyStrategy g3(options);
        ArenaOptions arena;
        arena.budget = candidates(800);
        const GameRecord record = play_game(start, {&r0, &g1, &r2, &g3}, arena);
        EXPECT_TRUE(record.finished) << "game " << game;
        greedy_wins += record.winner_team == 1 ? 1 : 0;
        ASSERT_EQ(record.seats.size(), 4u);
        for (int seat = 0; seat < 4; ++seat) {
            const auto& played = record.seats[static_cast<std::size_t>(seat)];
            EXPECT_GT(played.strokes, 0) << "game " << game << " seat " << seat;
            EXPECT_EQ(played.refusals, 0) << "game " << game << " seat " << seat;
        }
        EXPECT_EQ(record.scores.size(), 2u); // per team
    }
    EXPECT_GE(greedy_wins, 4);
}

TEST(DoublesArena, APlayerMissingForASeatPlaysNothing) {
    const rules::MatchState start = doubles(rules::RuleSet::Icf);
    RandomStrategy a(1);
    RandomStrategy b(2);
    const GameRecord record = play_game(start, {&a, &b}, ArenaOptions{});
    EXPECT_FALSE(record.finished);
    ASSERT_EQ(record.seats.size(), 4u);
    EXPECT_EQ(record.seats[0].strokes, 0);
}

} // namespace
} // namespace carrom::bots
