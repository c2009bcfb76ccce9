// Property tests: random games played to the end in every rule set, checking after every stroke
// that every piece is on the board or pocketed exactly once, nothing overlaps, the scores are
// what the pocket history implies, and the game ends within a bound. Thousands of games run on
// synthetic strokes (random pieces pocketed, positions unchanged); fewer through the exact engine
// with random legal shots. Fixed seeds: the same games every run.

#include "rules_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

namespace carrom::rules {
namespace {

constexpr int kSyntheticGames = 1500; // per rule set
constexpr RuleSet kAllRuleSets[] = {RuleSet::Icf, RuleSet::Seed, RuleSet::Freestyle,
                                    RuleSet::DiscPool};

// What the test itself remembers from the outcomes, to recompute scores independently.
struct Ledger {
    std::vector<int> striker_fouls{0, 0}; // per team
    std::vector<int> board_points{0, 0};  // icf: points won on finished boards
};

int team_pocketed_value(const MatchState& m, int team, const FreestylePoints& p) {
    int total = 0;
    for (const PocketedPiece& piece : m.pocketed) {
        if (team_of(m, piece.seat) != team) {
            continue;
        }
        total += piece.kind == BodyKind::White   ? p.white
                 : piece.kind == BodyKind::Black ? p.black
                                                 : 0;
    }
    return total;
}

int queen_bonus(const MatchState& m, int team, int points) {
    return m.queen.status == QueenStatus::Covered && team_of(m, m.queen.seat) == team ? points : 0;
}

int expected_score(const MatchState& m, int team, const Ledger& ledger) {
    const auto t = static_cast<std::size_t>(team);
    switch (m.rule_set) {
    case RuleSet::Icf:
        return ledger.board_points[t];
    case RuleSet::Seed:
        return 9 - count_on_board(m, *team_colour(m, team)) +
               queen_bonus(m, team, m.config.queen_points);
    case RuleSet::Freestyle:
        return team_pocketed_value(m, team, m.config.freestyle) +
               queen_bonus(m, team, m.config.freestyle.queen) -
               ledger.striker_fouls[t] * m.config.freestyle.striker_penalty;
    case RuleSet::DiscPool:
        return 9 - count_on_board(m, *team_colour(m, team));
    }
    return 0;
}

// icf: the board points, recomputed from the state before the stroke and the outcome.
int expected_board_points(const MatchState& after, const BoardResult& board, int shooter_team,
                          int score_before) {
    const RulesConfig& c = after.config;
    const BodyKind own = *team_colour(after, shooter_team);
    const BodyKind opp = own == BodyKind::White ? BodyKind::Black : BodyKind::White;
    int points = 0;
    switch (board.reason) {
    case RuleCode::OpponentLastCoin:
        points = c.queen_points + count_on_board(after, own);
        break;
    case RuleCode::OwnLastCoinBeforeQueen:
        points = c.queen_points;
        break;
    default:
        points =
            count_on_board(after, opp) + (score_before < c.queen_points_limit
                                              ? queen_bonus(after, shooter_team, c.queen_points)
                                              : 0);
        break;
    }
    return std::min(points, c.board_points_cap);
}

void check_pieces(const MatchState& m) {
    ASSERT_EQ(m.bodies.size(), 19u);
    for (int id = 0; id < 19; ++id) {
        const Body& body = m.bodies[static_cast<std::size_t>(id)];
        ASSERT_EQ(body.id, id);
        int listed = 0;
        for (const PocketedPiece& p : m.pocketed) {
            listed += p.id == id ? 1 : 0;
        }
        if (id == kQueenId && m.queen.status == QueenStatus::OutOfPlay) {
            ASSERT_TRUE(body.pocketed);
            ASSERT_EQ(listed, 0);
            continue;
        }
        ASSERT_LE(listed, 1) << "piece " << id << " pocketed twice";
        ASSERT_EQ(body.pocketed, listed == 1) << "piece " << id;
    }
    const bool queen_off =
        m.queen.status == QueenStatus::PendingCover || m.queen.status == QueenStatus::Covered;
    if (m.queen.status != QueenStatus::OutOfPlay) {
        ASSERT_EQ(m.bodies[0].pocketed, queen_off);
    }
    ASSERT_FALSE(test::overlaps_any(m));
    const auto scene_error = validate_scene(m.physics, m.bodies);
    ASSERT_FALSE(scene_error.has_value())
        << scene_error->code << " " << scene_error->body_id << " " << scene_error->message;
}

void check_after(const MatchState& before, const PlayResult& r, Ledger& ledger) {
    ASSERT_FALSE(r.error.has_value()) << to_string(r.error->code) << ": " << r.error->message;
    const MatchState& m = r.state;
    ASSERT_EQ(m.turn_number, before.turn_number + 1);
    const int team = team_of(before, r.outcome.seat);
    for (const Foul& foul : r.outcome.fouls) {
        if (foul.code == RuleCode::StrikerPocketed) {
            ledger.striker_fouls[static_cast<std::size_t>(team)] += 1;
        }
    }
    if (m.rule_set == RuleSet::Icf && r.outcome.board_end) {
        const BoardResult& board = *r.outcome.board_end;
        ASSERT_TRUE(board.winner_team.has_value());
        const auto w = static_cast<std::size_t>(*board.winner_team);
        ASSERT_EQ(board.points, expected_board_points(m, board, team, before.scores[w]));
        ledger.board_points[w] += board.points;
    }
    check_pieces(m);
    for (int t = 0; t < 2; ++t) {
        ASSERT_EQ(m.scores[static_cast<std::size_t>(t)], expected_score(m, t, ledger))
            << "team " << t << " after turn " << before.turn_number;
        ASSERT_EQ(r.outcome.score_changes[static_cast<std::size_t>(t)],
                  m.scores[static_cast<std::size_t>(t)] -
                      before.scores[static_cast<std::size_t>(t)]);
    }
}

// A random stroke without physics: each piece on the board drops with probability 0.1.
PlayResult synthetic_stroke(const MatchState& m, std::mt19937& rng) {
    std::bernoulli_distribution drop(0.1);
    std::bernoulli_distribution striker(0.1);
    std::bernoulli_distribution touched(0.95);
    std::bernoulli_distribution clock(0.02);
    if (clock(rng)) {
        return shot_clock_expired(m, m.turn_seat);
    }
    std::vector<int> ids;
    for (const Body& body : m.bodies) {
        if (!body.pocketed && drop(rng)) {
            ids.push_back(body.id);
        }
    }
    std::shuffle(ids.begin(), ids.end(), rng);
    StrokePhysics physics = test::pocketing(m, ids, striker(rng));
    physics.striker_touched_coin = touched(rng);
    if (!physics.striker_touched_coin) {
        physics = test::pocketing(m, {}, physics.striker_pocketed);
        physics.striker_touched_coin = false;
    }
    const StrokeResult r = judge_stroke(m, m.turn_seat, Shot{}, physics);
    return PlayResult{std::nullopt, r.state, r.outcome};
}

// A random legal shot: a free spot on the baseline, aimed near a random piece, random power.
Shot random_shot(const MatchState& m, std::mt19937& rng) {
    const double lo = baseline_x_min(m.physics);
    const double hi = baseline_x_max(m.physics);
    std::uniform_real_distribution<double> x(lo, hi);
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);
    std::uniform_real_distribution<double> power(2.0, m.physics.max_power);
    std::vector<Vec2> targets;
    for (const Body& body : m.bodies) {
        if (!body.pocketed) {
            targets.push_back(body.pos_px);
        }
    }
    Shot shot{x(rng), 0.0, power(rng)};
    for (int tries = 0; tries < 100 && check_placement(m, m.turn_seat, shot); ++tries) {
        shot.x_px = x(rng);
    }
    const Side side = m.seats[static_cast<std::size_t>(m.turn_seat)].side;
    const Vec2 from = striker_for(m.physics, side, shot).pos_px;
    std::uniform_int_distribution<std::size_t> pick(0, targets.size() - 1);
    const Vec2 to = targets.empty() ? m.physics.centre() : targets[pick(rng)];
    shot.angle_rad = std::atan2(to.y - from.y, to.x - from.x) + jitter(rng);
    return shot;
}

// Plays one game to the end; returns the number of turns it took (or -1 past max_turns).
int play_game(MatchState m, std::mt19937& rng, int max_turns, ExactEngine* engine) {
    Ledger ledger;
    for (int turn = 0; turn < max_turns; ++turn) {
        if (m.phase == Phase::GameOver) {
            EXPECT_TRUE(m.result.has_value());
            return turn;
        }
        if (m.phase == Phase::BoardOver) {
            m = start_next_board(m);
            check_pieces(m);
            continue;
        }
        PlayResult r;
        if (engine != nullptr) {
            const Shot shot = random_shot(m, rng);
            r = check_placement(m, m.turn_seat, shot) ? shot_clock_expired(m, m.turn_seat)
                                                      : play_shot(m, m.turn_seat, shot, *engine);
        } else {
            r = synthetic_stroke(m, rng);
        }
        check_after(m, r, ledger);
        if (::testing::Test::HasFatalFailure()) {
            return -1;
        }
        m = r.state;
    }
    return -1;
}

TEST(RulesProperty, ThousandsOfSyntheticGamesEndAndKeepTheInvariants) {
    for (RuleSet rule_set : kAllRuleSets) {
        std::mt19937 rng(20240601u + static_cast<unsigned>(rule_set));
        long turns = 0;
        int games = 0;
        for (int game = 0; game < kSyntheticGames; ++game) {
            RulesConfig config = test::no_clock();
            config.seat_count = game % 5 == 4 ? 4 : 2; // some doubles
            const int n = play_game(test::match(rule_set, config), rng, 20000, nullptr);
            ASSERT_GE(n, 0) << to_string(rule_set) << " game " << game << " did not end";
            turns += n;
            ++games;
        }
        EXPECT_EQ(games, kSyntheticGames);
        EXPECT_GT(turns, kSyntheticGames * 5L) << to_string(rule_set);
    }
}

TEST(RulesProperty, RandomGamesThroughThePhysicsEndAndKeepTheInvariants) {
    const PhysicsConfig physics;
    ExactEngine engine(physics);
    for (RuleSet rule_set : kAllRuleSets) {
        std::mt19937 rng(777u + static_cast<unsigned>(rule_set));
        // An icf game is several boards (about 500 strokes); the others one board.
        const int games = rule_set == RuleSet::Icf ? 100 : 500;
        for (int game = 0; game < games; ++game) {
            const int n = play_game(test::match(rule_set), rng, 5000, &engine);
            ASSERT_GE(n, 0) << to_string(rule_set) << " game " << game << " did not end";
        }
    }
}

} // namespace
} // namespace carrom::rules
