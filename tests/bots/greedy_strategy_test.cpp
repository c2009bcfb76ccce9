#include "bots/search_support.hpp"
#include "carrom/bots/arena.hpp"
#include "carrom/bots/greedy_strategy.hpp"
#include "carrom/bots/position_value.hpp"
#include "carrom/bots/random_strategy.hpp"
#include "carrom/bots/shot_candidates.hpp"
#include "carrom/bots/skill.hpp"
#include "carrom/bots/stroke_evaluator.hpp"
#include "carrom/rules/match.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace carrom::bots {
namespace {

using test::candidates;
using test::play;

constexpr double kDeg = std::numbers::pi / 180.0;

rules::MatchState match_of(rules::RuleSet rule_set) {
    rules::RulesConfig config;
    config.shot_clock_s = 0.0;
    return rules::new_match(rule_set, config, PhysicsConfig{});
}

// Takes piece id off the board as if seat had pocketed it earlier on this board.
void take_off(rules::MatchState& state, int id, int seat) {
    Body& body = state.bodies[static_cast<std::size_t>(id)];
    body.pocketed = true;
    state.pocketed.push_back(rules::PocketedPiece{id, body.kind, seat, 0});
}

// A board after the break with only the listed pieces left, at the given positions.
rules::MatchState sparse(rules::RuleSet rule_set, const std::vector<std::pair<int, Vec2>>& keep) {
    rules::MatchState state = match_of(rule_set);
    state.break_done = true;
    state.strokes_this_board = 1;
    for (const Body& body : std::vector<Body>(state.bodies)) {
        const bool kept = std::any_of(keep.begin(), keep.end(),
                                      [&](const auto& k) { return k.first == body.id; });
        if (!kept && !(rule_set == rules::RuleSet::DiscPool && body.id == kQueenId)) {
            take_off(state, body.id, 1);
        }
    }
    for (const auto& [id, pos] : keep) {
        state.bodies[static_cast<std::size_t>(id)].pos_px = pos;
    }
    return state;
}

int first_of(const rules::MatchState& state, BodyKind kind) {
    for (const Body& body : state.bodies) {
        if (body.kind == kind) {
            return body.id;
        }
    }
    return -1;
}

GreedyStrategy greedy(SkillLevel level, std::uint64_t seed = 1) {
    GreedyOptions options;
    options.level = level;
    options.seed = seed;
    return GreedyStrategy(options);
}

// --- skill levels ---------------------------------------------------------------------------

TEST(SkillLevel, NamesRoundTripAndUnknownNamesAreRejected) {
    for (const SkillLevel level :
         {SkillLevel::Perfect, SkillLevel::Hard, SkillLevel::Medium, SkillLevel::Easy}) {
        EXPECT_EQ(parse_skill_level(to_string(level)), level);
    }
    EXPECT_FALSE(parse_skill_level("godlike"));
    EXPECT_FALSE(parse_skill_level("Hard"));
}

TEST(SkillLevel, NoiseGrowsFromPerfectToEasy) {
    const ExecutionNoise perfect = noise_of(SkillLevel::Perfect);
    const ExecutionNoise hard = noise_of(SkillLevel::Hard);
    const ExecutionNoise medium = noise_of(SkillLevel::Medium);
    const ExecutionNoise easy = noise_of(SkillLevel::Easy);
    EXPECT_EQ(perfect.angle_sigma_rad, 0.0);
    EXPECT_EQ(perfect.power_sigma_fraction, 0.0);
    EXPECT_LT(hard.angle_sigma_rad, medium.angle_sigma_rad);
    EXPECT_LT(medium.angle_sigma_rad, easy.angle_sigma_rad);
    EXPECT_LT(hard.power_sigma_fraction, medium.power_sigma_fraction);
    EXPECT_LT(medium.power_sigma_fraction, easy.power_sigma_fraction);
}

TEST(SkillLevel, ZeroNoiseExecutesExactlyAndDrawsNothing) {
    std::mt19937_64 rng(3);
    std::mt19937_64 untouched(3);
    const Shot intended{250.0, -1.2, 17.5};
    const Shot executed = execute_with_noise(intended, ExecutionNoise{}, 25.0, rng);
    EXPECT_EQ(executed.x_px, intended.x_px);
    EXPECT_EQ(executed.angle_rad, intended.angle_rad);
    EXPECT_EQ(executed.power, intended.power);
    EXPECT_EQ(rng(), untouched());
}

TEST(SkillLevel, ExecutedShotsScatterWithTheLevelsSigmaAndStayInRange) {
    std::mt19937_64 rng(11);
    const ExecutionNoise noise = noise_of(SkillLevel::Easy);
    const Shot intended{300.0, -std::numbers::pi / 2.0, 10.0};
    constexpr int kDraws = 4000;
    double angle_sq = 0.0;
    double power_sq = 0.0;
    for (int i = 0; i < kDraws; ++i) {
        const Shot s = execute_with_noise(intended, noise, 25.0, rng);
        EXPECT_EQ(s.x_px, intended.x_px); // placement is never disturbed
        ASSERT_GE(s.power, 0.0);
        ASSERT_LE(s.power, 25.0);
        angle_sq += (s.angle_rad - intended.angle_rad) * (s.angle_rad - intended.angle_rad);
        power_sq += (s.power / intended.power - 1.0) * (s.power / intended.power - 1.0);
    }
    EXPECT_NEAR(std::sqrt(angle_sq / kDraws), noise.angle_sigma_rad, 0.05 * noise.angle_sigma_rad);
    EXPECT_NEAR(std::sqrt(power_sq / kDraws), noise.power_sigma_fraction,
                0.05 * noise.power_sigma_fraction);
}

TEST(SkillLevel, PowerNearTheMaximumIsClamped) {
    std::mt19937_64 rng(5);
    for (int i = 0; i < 500; ++i) {
        const Shot s =
            execute_with_noise(Shot{300.0, 0.0, 25.0}, noise_of(SkillLevel::Easy), 25.0, rng);
        ASSERT_LE(s.power, 25.0);
    }
}

// --- ranking and values ---------------------------------------------------------------------

TEST(RankAbove, AStrokeWithoutAFoulBeatsAnyFoulWhateverItsScore) {
    const RatedShot clean{Shot{}, false, -500.0};
    const RatedShot foul{Shot{}, true, 1e6};
    EXPECT_TRUE(rank_above(clean, foul));
    EXPECT_FALSE(rank_above(foul, clean));
}

TEST(RankAbove, ThenTheHigherScore) {
    EXPECT_TRUE(rank_above(RatedShot{Shot{}, false, 2.0}, RatedShot{Shot{}, false, 1.0}));
    EXPECT_FALSE(rank_above(RatedShot{Shot{}, false, 1.0}, RatedShot{Shot{}, false, 1.0}));
    EXPECT_TRUE(rank_above(RatedShot{Shot{}, true, 2.0}, RatedShot{Shot{}, true, 1.0}));
}

TEST(PositionValue, IcfOwnCoinsForOpponentCoinsAndDuesAgainst) {
    const ValueWeights w;
    rules::MatchState state = match_of(rules::RuleSet::Icf); // seat 0 breaks: team 0 white
    const double start = position_value(state, 0);
    EXPECT_DOUBLE_EQ(start, 0.0);
    rules::MatchState own = state;
    take_off(own, first_of(own, BodyKind::White), 0);
    EXPECT_DOUBLE_EQ(position_value(own, 0), w.own_coin);
    EXPECT_DOUBLE_EQ(position_value(own, 1), -w.opponent_coin);
    rules::MatchState due = state;
    due.dues_owed = {1, 0};
    EXPECT_DOUBLE_EQ(position_value(due, 0), -w.due);
    EXPECT_DOUBLE_EQ(position_value(due, 1), w.due);
}

TEST(PositionValue, IcfQueenCoveredAndPending) {
    const ValueWeights w;
    rules::MatchState state = match_of(rules::RuleSet::Icf);
    state.queen = {rules::QueenStatus::PendingCover, 0};
    EXPECT_DOUBLE_EQ(position_value(state, 0), w.queen_pending);
    EXPECT_DOUBLE_EQ(position_value(state, 1), -w.queen_pending);
    state.queen = {rules::QueenStatus::Covered, 1};
    EXPECT_DOUBLE_EQ(position_value(state, 1), w.queen_covered);
}

TEST(PositionValue, FreestyleAndSeedCountScorePoints) {
    const ValueWeights w;
    rules::MatchState freestyle = match_of(rules::RuleSet::Freestyle);
    freestyle.scores = {70, 20};
    EXPECT_DOUBLE_EQ(position_value(freestyle, 0), 50.0 * w.freestyle_point);
    EXPECT_DOUBLE_EQ(position_value(freestyle, 1), -50.0 * w.freestyle_point);
    rules::MatchState seed = match_of(rules::RuleSet::Seed);
    seed.scores = {2, 5};
    EXPECT_DOUBLE_EQ(position_value(seed, 1), 3.0 * w.seed_point);
}

TEST(PositionValue, TheGameResultDominates) {
    const ValueWeights w;
    rules::MatchState state = match_of(rules::RuleSet::Icf);
    state.phase = rules::Phase::GameOver;
    state.result = rules::GameResult{1, rules::RuleCode::BoardCleared};
    EXPECT_DOUBLE_EQ(position_value(state, 1), w.game_won);
    EXPECT_DOUBLE_EQ(position_value(state, 0), -w.game_won);
    state.result = rules::GameResult{std::nullopt, rules::RuleCode::CoinsExhausted};
    EXPECT_DOUBLE_EQ(position_value(state, 0), 0.0);
}

TEST(TurnValue, KeepingTheTurnCountsAndEasyCoinsGoToWhoeverShootsNext) {
    const ValueWeights w;
    // One white close to a pocket's edge: an easy coin for team 0 (white) in icf.
    rules::MatchState base = match_of(rules::RuleSet::Icf);
    const int w_id = first_of(base, BodyKind::White);
    const Vec2 pocket = base.physics.pocket_centres()[2]; // bottom-left
    rules::MatchState state = sparse(
        rules::RuleSet::Icf, {{w_id, pocket + Vec2{26.0, -26.0}}, {kQueenId, Vec2{300, 300}}});
    state.turn_seat = 0;
    const double easy = easy_coins(state, 0);
    EXPECT_GT(easy, 0.8);
    EXPECT_DOUBLE_EQ(easy_coins(state, 1), 0.0); // no black left; the queen is far from pockets
    EXPECT_DOUBLE_EQ(turn_value(state, 0), w.keep_turn + w.easy_coin * easy);
    state.turn_seat = 1;
    EXPECT_DOUBLE_EQ(turn_value(state, 0), 0.0); // the opponents have nothing easy
    EXPECT_DOUBLE_EQ(turn_value(state, 1), w.keep_turn);
}

// --- candidates -------------------------------------------------------------------------------

TEST(ShotCandidates, BaselinePositionsAreLegalSortedAndAvoidABlockingCoin) {
    rules::MatchState state = match_of(rules::RuleSet::Freestyle);
    const int coin = first_of(state, BodyKind::Black);
    state = sparse(rules::RuleSet::Freestyle, {{coin, Vec2{300.0, 520.0}}}); // on the baseline
    const StrokeEvaluator evaluator(state, 0);
    const std::vector<double> xs = legal_baseline_xs(evaluator, 9);
    ASSERT_FALSE(xs.empty());
    for (std::size_t i = 0; i < xs.size(); ++i) {
        EXPECT_TRUE(evaluator.placement_legal(xs[i]));
        EXPECT_GE(std::abs(xs[i] - 300.0), 32.0 - 1e-9); // never on the coin
        if (i > 0) {
            EXPECT_LT(xs[i - 1], xs[i]);
        }
    }
}

TEST(ShotCandidates, GridCoversTheSpreadAroundForward) {
    const rules::MatchState state = match_of(rules::RuleSet::Icf);
    GridSpec spec;
    spec.angle_steps = 5;
    spec.power_fractions = {0.5, 1.0};
    const std::vector<double> xs{150.0, 300.0};
    const std::vector<Shot> shots = grid_shots(state, 1, xs, spec);
    ASSERT_EQ(shots.size(), 2u * 5u * 2u);
    EXPECT_DOUBLE_EQ(shots.front().angle_rad, std::numbers::pi / 2.0 - spec.spread_rad);
    EXPECT_DOUBLE_EQ(shots[8].angle_rad, std::numbers::pi / 2.0 + spec.spread_rad);
    EXPECT_DOUBLE_EQ(shots[1].power, 25.0);
}

TEST(ShotCandidates, AnAimedShotPocketsALoneCoinWhenPlayedExactly) {
    // A white in the lower left quarter, nothing else: some aimed shot from the bottom seat
    // must pocket it, and aimed shots only go for coins the shooter wants.
    rules::MatchState state = match_of(rules::RuleSet::Icf);
    const int white = first_of(state, BodyKind::White);
    const int black = first_of(state, BodyKind::Black);
    state = sparse(rules::RuleSet::Icf, {{white, Vec2{160.0, 380.0}}, {black, Vec2{420.0, 200.0}}});
    const StrokeEvaluator evaluator(state, 0);
    const std::vector<double> xs = legal_baseline_xs(evaluator, 9);
    const std::vector<Shot> shots = aimed_shots(state, 0, xs, AimSpec{});
    ASSERT_FALSE(shots.empty());
    int pocketed_white = 0;
    for (const Shot& shot : shots) {
        const auto result = play(state, 0, shot);
        ASSERT_FALSE(result.error);
        for (const int id : result.outcome.pocketed) {
            pocketed_white += id == white ? 1 : 0;
        }
    }
    EXPECT_GT(pocketed_white, 0);
}

// --- the strategy ------------------------------------------------------------------------------

TEST(GreedyStrategy, PocketsALoneOwnCoinWithoutAFoul) {
    // icf, seat 0 plays white: two whites (so pocketing one does not end the board), one
    // black, the queen.
    rules::MatchState state = match_of(rules::RuleSet::Icf);
    const int white = first_of(state, BodyKind::White);
    state = sparse(rules::RuleSet::Icf, {{white, Vec2{230.0, 330.0}},
                                         {white + 2, Vec2{470.0, 120.0}},
                                         {first_of(state, BodyKind::Black), Vec2{420.0, 200.0}},
                                         {kQueenId, Vec2{300.0, 300.0}}});
    GreedyStrategy bot = greedy(SkillLevel::Perfect);
    const Shot shot = bot.choose_shot(state, 0, candidates(3000));
    const auto result = play(state, 0, shot);
    ASSERT_FALSE(result.error);
    EXPECT_TRUE(result.outcome.fouls.empty());
    EXPECT_NE(std::find(result.outcome.pocketed.begin(), result.outcome.pocketed.end(), white),
              result.outcome.pocketed.end());
}

TEST(GreedyStrategy, CoversThePendingQueen) {
    // icf: seat 0 (white) pocketed the queen last stroke; a white sits near a pocket.
    rules::MatchState state = match_of(rules::RuleSet::Icf);
    const int white = first_of(state, BodyKind::White);
    state = sparse(rules::RuleSet::Icf, {{white, Vec2{120.0, 200.0}},
                                         {first_of(state, BodyKind::Black), Vec2{420.0, 200.0}}});
    state.queen = {rules::QueenStatus::PendingCover, 0}; // sparse() took the queen off
    for (rules::PocketedPiece& piece : state.pocketed) {
        piece.seat = piece.id == kQueenId ? 0 : piece.seat;
    }
    GreedyStrategy bot = greedy(SkillLevel::Perfect);
    const Shot shot = bot.choose_shot(state, 0, candidates(3000));
    const auto result = play(state, 0, shot);
    ASSERT_FALSE(result.error);
    EXPECT_EQ(result.outcome.queen_after.status, rules::QueenStatus::Covered);
    EXPECT_TRUE(result.outcome.fouls.empty());
}

TEST(GreedyStrategy, NeverFoulsByChoiceOnRandomBoards) {
    // Random boards in every rule set, coins scattered near pockets (where the striker easily
    // follows a coin in): the stroke a perfect bot chooses never fouls.
    std::mt19937_64 rng(2024);
    const rules::RuleSet sets[] = {rules::RuleSet::Icf, rules::RuleSet::Seed,
                                   rules::RuleSet::Freestyle, rules::RuleSet::DiscPool};
    for (int trial = 0; trial < 8; ++trial) {
        const rules::RuleSet rule_set = sets[trial % 4];
        rules::MatchState state = match_of(rule_set);
        std::uniform_real_distribution<double> corner(60.0, 140.0);
        std::vector<std::pair<int, Vec2>> keep;
        for (int id = 1; id <= 8; ++id) {
            const auto pocket = state.physics.pocket_centres()[static_cast<std::size_t>(id % 4)];
            const Vec2 toward{pocket.x < 300 ? 1.0 : -1.0, pocket.y < 300 ? 1.0 : -1.0};
            const Vec2 pos = pocket + Vec2{toward.x * corner(rng), toward.y * corner(rng)};
            bool clear = true;
            for (const auto& k : keep) {
                clear = clear && length(k.second - pos) > 29.0;
            }
            if (clear) {
                keep.push_back({id, pos});
            }
        }
        state = sparse(rule_set, keep);
        state.turn_seat = trial % 2;
        GreedyStrategy bot = greedy(SkillLevel::Perfect, static_cast<std::uint64_t>(trial));
        const Shot shot = bot.choose_shot(state, state.turn_seat, candidates(2500));
        const auto result = play(state, state.turn_seat, shot);
        ASSERT_FALSE(result.error) << "trial " << trial;
        EXPECT_TRUE(result.outcome.fouls.empty()) << "trial " << trial;
        EXPECT_FALSE(bot.last_decision().chosen.foul);
    }
}

TEST(GreedyStrategy, NeverFoulsEvenWhenAFoulWouldScoreBest) {
    // Weights that make losing points attractive: pocketing the striker (-20 points in
    // freestyle) is then the best-scoring outcome, and the search finds such strokes; the bot
    // must still choose a stroke without a foul.
    rules::MatchState state = match_of(rules::RuleSet::Freestyle);
    state.break_done = true;
    GreedyOptions options;
    options.level = SkillLevel::Perfect;
    options.weights.freestyle_point = -1.0;
    GreedyStrategy bot(options);
    const Shot shot = bot.choose_shot(state, 0, candidates(2500));
    const auto result = play(state, 0, shot);
    ASSERT_FALSE(result.error);
    EXPECT_TRUE(result.outcome.fouls.empty());
    // ... although a foul was on offer: some grid shot pockets the striker.
    StrokeEvaluator evaluator(state, 0, options.weights);
    bool foul_found = false;
    for (const Shot& s : grid_shots(state, 0, legal_baseline_xs(evaluator, 9), GridSpec{})) {
        const RatedShot rated = evaluator.evaluate(s);
        if (rated.foul && rated.score > bot.last_decision().chosen.score) {
            foul_found = true;
            break;
        }
    }
    EXPECT_TRUE(foul_found);
}

TEST(GreedyStrategy, HonoursTheCandidateLimitAndReportsItsRate) {
    const rules::MatchState state = match_of(rules::RuleSet::Icf);
    GreedyStrategy bot = greedy(SkillLevel::Hard);
    bot.choose_shot(state, 0, candidates(400));
    EXPECT_GT(bot.last_decision().candidates, 300);
    EXPECT_LE(bot.last_decision().candidates, 400);
    EXPECT_FALSE(bot.last_decision().out_of_time);
    EXPECT_GT(bot.last_decision().candidates_per_s, 0.0);
    EXPECT_EQ(bot.search_totals().candidates, bot.last_decision().candidates);
}

TEST(GreedyStrategy, StopsAtTheTimeBudget) {
    const rules::MatchState state = match_of(rules::RuleSet::Icf);
    GreedyStrategy bot = greedy(SkillLevel::Hard);
    DecisionBudget budget;
    budget.time = std::chrono::milliseconds(1);
    bot.choose_shot(state, 0, budget);
    EXPECT_TRUE(bot.last_decision().out_of_time);
    EXPECT_GE(bot.last_decision().candidates, 1);
    EXPECT_LT(bot.last_decision().seconds, 0.25); // 1 ms plus one candidate, with slack
}

TEST(GreedyStrategy, SameSeedSameShotWhenTheCandidateLimitEndsTheSearch) {
    const rules::MatchState state = match_of(rules::RuleSet::Freestyle);
    GreedyStrategy a = greedy(SkillLevel::Medium, 9);
    GreedyStrategy b = greedy(SkillLevel::Medium, 9);
    const Shot sa = a.choose_shot(state, 0, candidates(600));
    const Shot sb = b.choose_shot(state, 0, candidates(600));
    EXPECT_EQ(sa.x_px, sb.x_px);
    EXPECT_EQ(sa.angle_rad, sb.angle_rad);
    EXPECT_EQ(sa.power, sb.power);
}

TEST(GreedyStrategy, ExecutionNoiseMovesTheShotOffTheIntendedOne) {
    const rules::MatchState state = match_of(rules::RuleSet::Freestyle);
    GreedyStrategy perfect = greedy(SkillLevel::Perfect);
    const Shot exact = perfect.choose_shot(state, 0, candidates(300));
    EXPECT_EQ(exact.angle_rad, perfect.last_decision().chosen.shot.angle_rad);
    GreedyStrategy easy = greedy(SkillLevel::Easy);
    const Shot noisy = easy.choose_shot(state, 0, candidates(300));
    EXPECT_NE(noisy.angle_rad, easy.last_decision().chosen.shot.angle_rad);
    EXPECT_EQ(noisy.x_px, easy.last_decision().chosen.shot.x_px);
}

TEST(GreedyStrategy, ARefusedShotIsNotChosenAgainForTheSameTurn) {
    const rules::MatchState state = match_of(rules::RuleSet::Icf);
    GreedyStrategy bot = greedy(SkillLevel::Perfect);
    const Shot first = bot.choose_shot(state, 0, candidates(300));
    bot.shot_refused();
    const Shot second = bot.choose_shot(state, 0, candidates(300));
    EXPECT_TRUE(first.x_px != second.x_px || first.angle_rad != second.angle_rad ||
                first.power != second.power);
}

// --- games ------------------------------------------------------------------------------------

// Always asks for an impossible power.
class IllegalStrategy final : public Strategy {
public:
    std::string_view name() const override { return "illegal"; }
    Shot choose_shot(const rules::MatchState&, int, const DecisionBudget&) override {
        return Shot{300.0, 0.0, 1000.0};
    }
};

TEST(Arena, ASeatThatKeepsShootingIllegallyForfeits) {
    const rules::MatchState start = match_of(rules::RuleSet::Icf);
    IllegalStrategy illegal;
    RandomStrategy random(1);
    ArenaOptions options;
    const GameRecord record = play_game(start, {&illegal, &random}, options);
    EXPECT_TRUE(record.finished);
    EXPECT_EQ(record.winner_team, 1);
    EXPECT_EQ(record.reason, rules::RuleCode::Forfeit);
    EXPECT_EQ(record.seats[0].refusals, options.max_refusals + 1);
    EXPECT_EQ(record.seats[0].strokes, 0);
}

TEST(Arena, GreedyBeatsRandomInEveryRuleSet) {
    for (const rules::RuleSet rule_set : {rules::RuleSet::Icf, rules::RuleSet::Seed,
                                          rules::RuleSet::Freestyle, rules::RuleSet::DiscPool}) {
        rules::RulesConfig config;
        config.shot_clock_s = 0.0;
        config.target_points = 10; // icf: a short game
        const rules::MatchState start = rules::new_match(rule_set, config, PhysicsConfig{});
        GreedyStrategy bot = greedy(SkillLevel::Hard, 3);
        RandomStrategy random(4);
        ArenaOptions options;
        options.budget = candidates(1500);
        const GameRecord record = play_game(start, {&random, &bot}, options);
        EXPECT_TRUE(record.finished) << rules::to_string(rule_set);
        EXPECT_EQ(record.winner_team, 1) << rules::to_string(rule_set);
        EXPECT_EQ(record.seats[1].refusals, 0);
        EXPECT_GT(record.seats[1].strokes, 0);
        EXPECT_GT(record.seats[1].candidates, 0);
    }
}

} // namespace
} // namespace carrom::bots
