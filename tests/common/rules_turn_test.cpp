// Turns, placement, shot clock, forfeit, seats, names and config: the rules around the strokes.

#include "rules_support.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace carrom::rules {
namespace {

using test::stroke;

TEST(RulesNames, RuleSetsRoundTrip) {
    for (RuleSet r : {RuleSet::Icf, RuleSet::Seed, RuleSet::Freestyle, RuleSet::DiscPool}) {
        RuleSet parsed = RuleSet::Icf;
        ASSERT_TRUE(parse_rule_set(to_string(r), parsed)) << to_string(r);
        EXPECT_EQ(parsed, r);
    }
    EXPECT_EQ(to_string(RuleSet::DiscPool), "discpool");
    RuleSet out = RuleSet::Seed;
    EXPECT_FALSE(parse_rule_set("ICF", out));
    EXPECT_FALSE(parse_rule_set("", out));
    EXPECT_EQ(out, RuleSet::Seed);
}

TEST(RulesNames, RuleCodesRoundTrip) {
    for (int i = 0; i <= static_cast<int>(RuleCode::BoardsPlayed); ++i) {
        const auto code = static_cast<RuleCode>(i);
        RuleCode parsed = RuleCode::Forfeit;
        ASSERT_TRUE(parse_rule_code(to_string(code), parsed)) << i;
        EXPECT_EQ(parsed, code);
    }
    EXPECT_EQ(to_string(RuleCode::OwnLastCoinBeforeQueen), "own_last_coin_before_queen");
    RuleCode out = RuleCode::Forfeit;
    EXPECT_FALSE(parse_rule_code("foul", out));
}

TEST(RulesNames, SidesRoundTrip) {
    for (Side s : {Side::Bottom, Side::Right, Side::Top, Side::Left}) {
        Side parsed = Side::Bottom;
        ASSERT_TRUE(parse_side(to_string(s), parsed));
        EXPECT_EQ(parsed, s);
    }
    Side out = Side::Left;
    EXPECT_FALSE(parse_side("north", out));
}

TEST(RulesConfigCheck, DefaultsAreValid) {
    EXPECT_FALSE(validate_rules_config(RulesConfig{}).has_value());
    EXPECT_EQ(RulesConfig{}.target_points, 25);
    EXPECT_EQ(RulesConfig{}.max_boards, 8);
    EXPECT_EQ(RulesConfig{}.shot_clock_s, 20.0);
    EXPECT_EQ(RulesConfig{}.freestyle.target, 170);
}

TEST(RulesConfigCheck, EachBadFieldIsNamed) {
    RulesConfig c;
    c.seat_count = 3;
    EXPECT_EQ(validate_rules_config(c)->field, "seat_count");
    c = {};
    c.first_breaker = 2;
    EXPECT_EQ(validate_rules_config(c)->field, "first_breaker");
    c = {};
    c.shot_clock_s = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(validate_rules_config(c)->field, "shot_clock_s");
    c = {};
    c.shot_clock_s = -1.0;
    EXPECT_EQ(validate_rules_config(c)->field, "shot_clock_s");
    c = {};
    c.target_points = 0;
    EXPECT_EQ(validate_rules_config(c)->code, RuleErrorCode::InvalidConfig);
    EXPECT_EQ(validate_rules_config(c)->field, "target_points");
    c = {};
    c.freestyle.black = -1;
    EXPECT_EQ(validate_rules_config(c)->field, "freestyle.black");
    c = {};
    c.seat_count = 4;
    c.first_breaker = 3;
    EXPECT_FALSE(validate_rules_config(c).has_value());
}

TEST(RulesSeats, SinglesAndDoubles) {
    const std::vector<Seat> two = make_seats(2);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[1].side, Side::Top);
    EXPECT_EQ(two[1].team, 1);
    EXPECT_EQ(two[0].partner, -1);
    const std::vector<Seat> four = make_seats(4);
    ASSERT_EQ(four.size(), 4u);
    EXPECT_EQ(four[1].side, Side::Right); // anticlockwise on screen: bottom, right, top, left
    EXPECT_EQ(four[2].side, Side::Top);
    EXPECT_EQ(four[3].side, Side::Left);
    EXPECT_EQ(four[0].partner, 2);
    EXPECT_EQ(four[3].partner, 1);
    EXPECT_EQ(four[2].team, 0);
    EXPECT_EQ(four[3].team, 1);
    EXPECT_EQ(next_seat(3, 4), 0);
    EXPECT_EQ(next_seat(1, 2), 0);
}

TEST(RulesSeats, DoublesTurnsPassAnticlockwiseAndPartnersShareColourAndDues) {
    RulesConfig config = test::no_clock();
    config.seat_count = 4;
    MatchState m = test::broken(RuleSet::Icf, config);
    EXPECT_EQ(m.scores.size(), 2u);
    EXPECT_EQ(team_colour(m, team_of(m, 2)), BodyKind::White);
    m = stroke(m, {}).state;
    EXPECT_EQ(m.turn_seat, 1);
    m = stroke(m, {}, true).state; // seat 1 (team 1) owes a due
    EXPECT_EQ(m.dues_owed, (std::vector<int>{0, 1}));
    m = stroke(m, {}).state;
    EXPECT_EQ(m.turn_seat, 3);
    const StrokeResult r = stroke(m, {1}); // seat 3 pockets black, team 1's: pays the due
    EXPECT_EQ(r.outcome.dues_paid, 1);
    EXPECT_EQ(r.state.turn_seat, 3);
}

TEST(RulesSeats, DoublesStrikerSitsOnTheSideBaselines) {
    const PhysicsConfig physics;
    const Shot shot{200.0, 0.0, 1.0};
    EXPECT_EQ(striker_for(physics, Side::Bottom, shot).pos_px, (Vec2{200.0, 520.0}));
    EXPECT_EQ(striker_for(physics, Side::Top, shot).pos_px, (Vec2{200.0, 80.0}));
    EXPECT_EQ(striker_for(physics, Side::Left, shot).pos_px, (Vec2{80.0, 200.0}));
    EXPECT_EQ(striker_for(physics, Side::Right, shot).pos_px, (Vec2{520.0, 200.0}));
    const Body s = striker_for(physics, Side::Left, Shot{200.0, 0.0, 2.0});
    EXPECT_EQ(s.id, kStrikerId);
    EXPECT_EQ(s.kind, BodyKind::Striker);
    EXPECT_DOUBLE_EQ(s.vel_px_s.x, 120.0);
}

TEST(RulesTurn, TurnChecksExplainThemselves) {
    const MatchState m = test::match(RuleSet::Icf);
    EXPECT_FALSE(check_turn(m, 0).has_value());
    EXPECT_EQ(check_turn(m, 1)->code, RuleErrorCode::NotYourTurn);
    EXPECT_EQ(check_turn(m, 2)->code, RuleErrorCode::InvalidSeat);
    EXPECT_EQ(check_turn(m, -1)->code, RuleErrorCode::InvalidSeat);
    MatchState over = m;
    over.phase = Phase::BoardOver;
    EXPECT_EQ(check_turn(over, 0)->code, RuleErrorCode::BoardOver);
    over.phase = Phase::GameOver;
    EXPECT_EQ(check_turn(over, 0)->code, RuleErrorCode::GameOver);
}

TEST(RulesTurn, AnInputForAnotherTurnIsStale) {
    MatchState m = test::match(RuleSet::Icf);
    m.turn_number = 4;
    EXPECT_FALSE(check_turn(m, 0, 4).has_value());
    const auto stale = check_turn(m, 0, 3);
    ASSERT_TRUE(stale.has_value());
    EXPECT_EQ(stale->code, RuleErrorCode::StaleTurn);
    EXPECT_EQ(stale->message, "That input was for turn 3; the turn is 4.");
    // Whose turn it is comes first: the other seat is told so, whatever turn it names.
    EXPECT_EQ(check_turn(m, 1, 3)->code, RuleErrorCode::NotYourTurn);
    EXPECT_EQ(check_turn(m, 1, 3)->message, "It is seat 0's turn.");
}

TEST(RulesTurn, RuleErrorCodesHaveStableNames) {
    EXPECT_EQ(to_string(RuleErrorCode::InvalidSeat), "invalid_seat");
    EXPECT_EQ(to_string(RuleErrorCode::NotYourTurn), "not_your_turn");
    EXPECT_EQ(to_string(RuleErrorCode::StaleTurn), "stale_turn");
    EXPECT_EQ(to_string(RuleErrorCode::StrikerOverlaps), "striker_overlaps");
    EXPECT_EQ(to_string(RuleErrorCode::PowerOutOfRange), "power_out_of_range");
    EXPECT_EQ(to_string(RuleErrorCode::PhysicsError), "physics_error");
    EXPECT_EQ(to_string(RuleErrorCode::InvalidConfig), "invalid_config");
    EXPECT_EQ(to_string(RuleErrorCode::WrongPhase), "wrong_phase");
}

TEST(RulesPlacement, LegalShotPasses) {
    const MatchState m = test::match(RuleSet::Icf);
    EXPECT_FALSE(check_placement(m, 0, Shot{300.0, -1.57, 25.0}).has_value());
    EXPECT_FALSE(check_placement(m, 1, Shot{113.0, 1.0, 0.0}).has_value());
    EXPECT_FALSE(check_placement(m, 0, Shot{487.0, 0.0, 12.5}).has_value());
}

TEST(RulesPlacement, IllegalPlacementsAreRejectedWithAReason) {
    MatchState m = test::match(RuleSet::Icf);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(check_placement(m, 0, Shot{nan, 0.0, 1.0})->code, RuleErrorCode::XNotFinite);
    EXPECT_EQ(check_placement(m, 0, Shot{112.9, 0.0, 1.0})->code, RuleErrorCode::XOutOfRange);
    EXPECT_EQ(check_placement(m, 0, Shot{487.1, 0.0, 1.0})->code, RuleErrorCode::XOutOfRange);
    EXPECT_EQ(check_placement(m, 0, Shot{300.0, inf, 1.0})->code, RuleErrorCode::AngleNotFinite);
    EXPECT_EQ(check_placement(m, 0, Shot{300.0, 0.0, nan})->code, RuleErrorCode::PowerNotFinite);
    EXPECT_EQ(check_placement(m, 0, Shot{300.0, 0.0, -0.1})->code, RuleErrorCode::PowerOutOfRange);
    EXPECT_EQ(check_placement(m, 0, Shot{300.0, 0.0, 25.1})->code, RuleErrorCode::PowerOutOfRange);
    EXPECT_EQ(check_placement(m, 5, Shot{300.0, 0.0, 1.0})->code, RuleErrorCode::InvalidSeat);
    test::put(m, 3, {250.0, 510.0});
    const auto overlap = check_placement(m, 0, Shot{270.0, 0.0, 1.0});
    ASSERT_TRUE(overlap.has_value());
    EXPECT_EQ(overlap->code, RuleErrorCode::StrikerOverlaps);
    EXPECT_EQ(overlap->field, "shot.x");
    EXPECT_NE(overlap->message.find("piece 3"), std::string::npos);
    // Touching is allowed: 32 px apart along x, at the same y.
    test::put(m, 3, {250.0, 520.0});
    EXPECT_FALSE(check_placement(m, 0, Shot{282.0, 0.0, 1.0}).has_value());
    // A pocketed piece is not in the way.
    test::pre_pocket(m, 3, 1);
    EXPECT_FALSE(check_placement(m, 0, Shot{250.0, 0.0, 1.0}).has_value());
}

TEST(RulesPlacement, PlayShotRejectsWithoutChangingAnything) {
    MatchState m = test::match(RuleSet::Icf);
    test::put(m, 3, {250.0, 520.0});
    ExactEngine engine(m.physics);
    const PlayResult r = play_shot(m, 0, Shot{260.0, -1.0, 5.0}, engine);
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->code, RuleErrorCode::StrikerOverlaps);
    EXPECT_EQ(r.state.turn_number, m.turn_number);
    EXPECT_EQ(r.state.bodies[3].pos_px, (Vec2{250.0, 520.0}));
    const PlayResult wrong_seat = play_shot(m, 1, Shot{300.0, 1.0, 5.0}, engine);
    EXPECT_EQ(wrong_seat.error->code, RuleErrorCode::NotYourTurn);
}

TEST(RulesClock, RanOutOnlyPastTheClockPlusGrace) {
    MatchState m = test::match(RuleSet::Icf, RulesConfig{});
    EXPECT_FALSE(shot_clock_ran_out(m, 20.0));
    EXPECT_FALSE(shot_clock_ran_out(m, 20.5));
    EXPECT_TRUE(shot_clock_ran_out(m, 20.51));
    m.config.shot_clock_s = 0.0;
    EXPECT_FALSE(shot_clock_ran_out(m, 1e9));
}

TEST(RulesClock, ExpiryPassesTheTurn) {
    const MatchState m = test::match(RuleSet::Icf);
    const PlayResult r = shot_clock_expired(m, 0);
    ASSERT_FALSE(r.error.has_value());
    EXPECT_EQ(r.state.turn_seat, 1);
    EXPECT_EQ(r.state.turn_number, 1);
    EXPECT_EQ(r.state.missed_turns, (std::vector<int>{1, 0}));
    EXPECT_FALSE(r.outcome.shot_taken);
    ASSERT_EQ(r.outcome.fouls.size(), 1u);
    EXPECT_EQ(r.outcome.fouls[0].code, RuleCode::ShotClockExpired);
    EXPECT_EQ(shot_clock_expired(m, 1).error->code, RuleErrorCode::NotYourTurn);
}

TEST(RulesClock, ThreeMissedTurnsInARowLoseTheGame) {
    for (RuleSet rule_set : {RuleSet::Icf, RuleSet::Seed, RuleSet::Freestyle, RuleSet::DiscPool}) {
        MatchState m = test::match(rule_set);
        for (int i = 0; i < 2; ++i) {
            m = shot_clock_expired(m, 0).state;
            m = stroke(m, {}).state; // seat 1 shoots
        }
        const PlayResult r = shot_clock_expired(m, 0);
        EXPECT_EQ(r.state.phase, Phase::GameOver) << to_string(rule_set);
        ASSERT_TRUE(r.outcome.game_end.has_value());
        EXPECT_EQ(r.outcome.game_end->winner_team, 1);
        EXPECT_EQ(r.outcome.game_end->reason, RuleCode::MissedTurns);
        EXPECT_EQ(shot_clock_expired(r.state, 1).error->code, RuleErrorCode::GameOver);
    }
}

TEST(RulesClock, AStrokeResetsTheMissedCount) {
    MatchState m = test::broken(RuleSet::Icf);
    m = shot_clock_expired(m, 0).state;
    m = shot_clock_expired(m, 1).state;
    m = shot_clock_expired(m, 0).state;
    EXPECT_EQ(m.missed_turns, (std::vector<int>{2, 1}));
    m = stroke(m, {}).state; // seat 1 shoots
    m = stroke(m, {}).state; // seat 0 shoots
    EXPECT_EQ(m.missed_turns, (std::vector<int>{0, 0}));
    m = shot_clock_expired(m, 1).state;
    m = shot_clock_expired(m, 0).state;
    EXPECT_EQ(m.phase, Phase::AwaitingShot);
}

TEST(RulesClock, ExpiryOnTheCoverStrokeReturnsTheQueen) {
    MatchState m = test::broken(RuleSet::Icf);
    test::pre_pocket(m, 2, 0);
    m = stroke(m, {kQueenId}).state;
    ASSERT_EQ(m.queen.status, QueenStatus::PendingCover);
    const PlayResult r = shot_clock_expired(m, 0);
    EXPECT_EQ(r.state.queen.status, QueenStatus::OnBoard);
    EXPECT_FALSE(r.state.bodies[kQueenId].pocketed);
    ASSERT_EQ(r.outcome.returned.size(), 1u);
    EXPECT_EQ(r.outcome.returned[0].reason, RuleCode::QueenNotCovered);
}

TEST(RulesForfeit, TheForfeitingTeamLoses) {
    const MatchState m = test::match(RuleSet::Icf);
    const PlayResult r = forfeit(m, 1); // not seat 1's turn: still allowed
    ASSERT_FALSE(r.error.has_value());
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    EXPECT_EQ(r.state.result->winner_team, 0);
    EXPECT_EQ(r.state.result->reason, RuleCode::Forfeit);
    EXPECT_EQ(r.state.turn_number, 1);
    EXPECT_EQ(forfeit(r.state, 0).error->code, RuleErrorCode::GameOver);
    EXPECT_EQ(forfeit(m, 7).error->code, RuleErrorCode::InvalidSeat);
}

} // namespace
} // namespace carrom::rules
