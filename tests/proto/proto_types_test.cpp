// Wire names of enums and identifier checks.
#include "carrom/proto/types.hpp"

#include <gtest/gtest.h>

namespace carrom::proto {
namespace {

template <class E> void expect_round_trip(E value, std::string_view name) {
    EXPECT_EQ(to_string(value), name);
    E parsed{};
    ASSERT_TRUE(parse(name, parsed)) << name;
    EXPECT_EQ(parsed, value);
}

TEST(ProtoTypes, EnumNames) {
    expect_round_trip(RuleSet::Icf, "icf");
    expect_round_trip(RuleSet::Seed, "seed");
    expect_round_trip(RuleSet::Freestyle, "freestyle");
    expect_round_trip(RuleSet::DiscPool, "discpool");
    expect_round_trip(Role::Player, "player");
    expect_round_trip(Role::Spectator, "spectator");
    expect_round_trip(Colour::None, "none");
    expect_round_trip(Colour::Black, "black");
    expect_round_trip(Colour::White, "white");
    expect_round_trip(Phase::Waiting, "waiting");
    expect_round_trip(Phase::Aiming, "aiming");
    expect_round_trip(Phase::Moving, "moving");
    expect_round_trip(Phase::BoardOver, "board_over");
    expect_round_trip(Phase::GameOver, "game_over");
    expect_round_trip(QueenState::OnBoard, "on_board");
    expect_round_trip(QueenState::Pending, "pending");
    expect_round_trip(QueenState::Covered, "covered");
    expect_round_trip(QueenState::None, "none");
    expect_round_trip(BotLevel::Random, "random");
    expect_round_trip(BotLevel::Hard, "hard");
}

TEST(ProtoTypes, ParseRejectsNearMisses) {
    RuleSet rule_set = RuleSet::Seed;
    EXPECT_FALSE(parse("ICF", rule_set));
    EXPECT_FALSE(parse("icf ", rule_set));
    EXPECT_FALSE(parse("", rule_set));
    EXPECT_EQ(rule_set, RuleSet::Seed); // untouched on failure
    BodyKind kind = BodyKind::Black;
    EXPECT_TRUE(parse("striker", kind));
    EXPECT_EQ(kind, BodyKind::Striker);
    Baseline baseline = Baseline::Bottom;
    EXPECT_TRUE(parse("top", baseline));
    EXPECT_EQ(baseline, Baseline::Top);
    EXPECT_EQ(baseline_name(Baseline::Bottom), "bottom");
    EXPECT_EQ(body_kind_name(BodyKind::Queen), "queen");
}

TEST(ProtoTypes, RoomCodes) {
    EXPECT_TRUE(is_room_code("ABCDEF"));
    EXPECT_TRUE(is_room_code("Z23456"));
    EXPECT_FALSE(is_room_code("ABCDE"));
    EXPECT_FALSE(is_room_code("ABCDEFG"));
    EXPECT_FALSE(is_room_code("ABCDEI")); // I is ambiguous
    EXPECT_FALSE(is_room_code("ABCDEL")); // L is ambiguous
    EXPECT_FALSE(is_room_code("ABCDE0"));
    EXPECT_FALSE(is_room_code(std::string_view("ABCDE\0", 6)));
}

TEST(ProtoTypes, ResumeTokens) {
    EXPECT_TRUE(is_resume_token("0123456789abcdef0123456789abcdef"));
    EXPECT_FALSE(is_resume_token("0123456789ABCDEF0123456789abcdef"));
    EXPECT_FALSE(is_resume_token("0123456789abcdef0123456789abcde"));
    EXPECT_FALSE(is_resume_token(""));
}

TEST(ProtoTypes, PlayerNames) {
    EXPECT_TRUE(is_player_name("A"));
    EXPECT_TRUE(is_player_name("Asha K"));
    EXPECT_FALSE(is_player_name(""));
    EXPECT_FALSE(is_player_name(" "));
    EXPECT_FALSE(is_player_name("a\nb"));
    EXPECT_FALSE(is_player_name(std::string(25, 'a')));
}

TEST(ProtoTypes, BodyConversionKeepsEveryField) {
    Body body;
    body.id = 7;
    body.kind = BodyKind::White;
    body.pos_px = {1.5, 2.5};
    body.vel_px_s = {-3.0, 4.0};
    body.pocketed = true;
    const BoardBody board = to_board_body(body);
    EXPECT_EQ(board, (BoardBody{7, BodyKind::White, {1.5, 2.5}, {-3.0, 4.0}, true}));
    const Body back = to_body(board);
    EXPECT_EQ(back.id, 7);
    EXPECT_EQ(back.kind, BodyKind::White);
    EXPECT_EQ(back.pos_px, (Vec2{1.5, 2.5}));
    EXPECT_EQ(back.vel_px_s, (Vec2{-3.0, 4.0}));
    EXPECT_TRUE(back.pocketed);
}

} // namespace
} // namespace carrom::proto
