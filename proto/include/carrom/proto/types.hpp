#pragma once
// Value types shared by several messages, with their wire names. Each enum maps to one lowercase
// string on the wire; parse_* return false for any other string.

#include "carrom/body.hpp"
#include "carrom/enum_names.hpp"
#include "carrom/rules/rule_set.hpp"
#include "carrom/rules/seat.hpp"
#include "carrom/scene.hpp"
#include "carrom/vec2.hpp"

#include <cstdint>
#include <optional>
#include <string_view>

namespace carrom::proto {

enum class RuleSet : std::uint8_t {
    Icf,
    Seed,
    Freestyle,
    DiscPool
};                                                       // "icf" "seed" "freestyle" "discpool"
enum class Role : std::uint8_t { Player, Spectator };    // "player" "spectator"
enum class Colour : std::uint8_t { None, Black, White }; // "none" "black" "white"
enum class Phase : std::uint8_t { Waiting, Aiming, Moving, BoardOver, GameOver };
// "waiting" (a seat is empty), "aiming" (to_play may shoot), "moving" (a shot is streaming),
// "board_over" (between boards), "game_over" (rematch possible)
enum class QueenState : std::uint8_t { OnBoard, Pending, Covered, None };
// "on_board" "pending" "covered" "none" (a rule set without a queen: discpool)
enum class BotLevel : std::uint8_t { Random, Easy, Medium, Hard }; // "random" "easy" ...
// A quick reaction a seated player sends during a match (the "emote" message): a fixed set, no
// free text. "nice_shot" "good_game" "well_played" "thanks" "good_luck" "oops" "wow" "sorry"
enum class Emote : std::uint8_t {
    NiceShot,
    GoodGame,
    WellPlayed,
    Thanks,
    GoodLuck,
    Oops,
    Wow,
    Sorry
};
// The side of the board a seat shoots from: "bottom" "right" "top" "left" (the rules engine's
// seat sides, in seat order: singles uses bottom and top). Not carrom::Baseline, which names
// the two baselines of a scene file.
using Baseline = rules::Side;

// Wire names (enum_names.hpp); Baseline's are rules::kSideNames, BodyKind's kBodyKindNames.
inline constexpr enum_names::Table<RuleSet, 4> kRuleSetNames{{{RuleSet::Icf, "icf"},
                                                              {RuleSet::Seed, "seed"},
                                                              {RuleSet::Freestyle, "freestyle"},
                                                              {RuleSet::DiscPool, "discpool"}}};
inline constexpr enum_names::Table<Role, 2> kRoleNames{
    {{Role::Player, "player"}, {Role::Spectator, "spectator"}}};
inline constexpr enum_names::Table<Colour, 3> kColourNames{
    {{Colour::None, "none"}, {Colour::Black, "black"}, {Colour::White, "white"}}};
inline constexpr enum_names::Table<Phase, 5> kPhaseNames{{{Phase::Waiting, "waiting"},
                                                          {Phase::Aiming, "aiming"},
                                                          {Phase::Moving, "moving"},
                                                          {Phase::BoardOver, "board_over"},
                                                          {Phase::GameOver, "game_over"}}};
inline constexpr enum_names::Table<QueenState, 4> kQueenStateNames{
    {{QueenState::OnBoard, "on_board"},
     {QueenState::Pending, "pending"},
     {QueenState::Covered, "covered"},
     {QueenState::None, "none"}}};
inline constexpr enum_names::Table<BotLevel, 4> kBotLevelNames{{{BotLevel::Random, "random"},
                                                                {BotLevel::Easy, "easy"},
                                                                {BotLevel::Medium, "medium"},
                                                                {BotLevel::Hard, "hard"}}};

inline constexpr enum_names::Table<Emote, 8> kEmoteNames{{{Emote::NiceShot, "nice_shot"},
                                                          {Emote::GoodGame, "good_game"},
                                                          {Emote::WellPlayed, "well_played"},
                                                          {Emote::Thanks, "thanks"},
                                                          {Emote::GoodLuck, "good_luck"},
                                                          {Emote::Oops, "oops"},
                                                          {Emote::Wow, "wow"},
                                                          {Emote::Sorry, "sorry"}}};

std::string_view to_string(RuleSet value);
// The rules engine's rule set for a wire rule set (the two enums list the same rule sets).
rules::RuleSet to_rules(RuleSet value);
std::string_view to_string(Role value);
std::string_view to_string(Colour value);
std::string_view to_string(Phase value);
std::string_view to_string(QueenState value);
std::string_view to_string(BotLevel value);
std::string_view to_string(Emote value);
std::string_view baseline_name(Baseline value);  // "bottom" "right" "top" "left"
std::string_view body_kind_name(BodyKind value); // "black" "white" "queen" "striker"

bool parse(std::string_view text, RuleSet& out);
bool parse(std::string_view text, Role& out);
bool parse(std::string_view text, Colour& out);
bool parse(std::string_view text, Phase& out);
bool parse(std::string_view text, QueenState& out);
bool parse(std::string_view text, BotLevel& out);
bool parse(std::string_view text, Emote& out);
bool parse(std::string_view text, Baseline& out);
bool parse(std::string_view text, BodyKind& out);

// Identifier checks (exact; no normalisation).
bool is_room_code(std::string_view text);    // 6 characters of kRoomCodeAlphabet
bool is_resume_token(std::string_view text); // 32 lowercase hex digits
bool is_identity_key(std::string_view text); // 64 lowercase hex digits (kIdentityKeyLength)
// A player name: 1..kMaxNameBytes bytes, no ASCII control characters, not all spaces.
// (The JSON parser has already rejected invalid UTF-8.)
bool is_player_name(std::string_view text);

// One body of a full board (room_state). Pocketed bodies keep their last position. The wire's
// form of carrom::Body (same fields, px and px/s as the server's engine has them, plus ==
// for the message round trips; to_board_body / to_body convert), kept apart from the engine's
// type so the protocol owns what it sends; client::BodyState is the client's own copy.
struct BoardBody {
    int id = 0;
    BodyKind kind = BodyKind::Black;
    Vec2 pos_px{};
    Vec2 vel_px_s{};
    bool pocketed = false;
    friend bool operator==(const BoardBody&, const BoardBody&) = default;
};
BoardBody to_board_body(const Body& body);
Body to_body(const BoardBody& body);

// Queen: on the board, pocketed and awaiting cover by `seat`, or covered by `seat`.
struct QueenInfo {
    QueenState state = QueenState::OnBoard;
    int seat = -1; // -1 when on the board
    friend bool operator==(const QueenInfo&, const QueenInfo&) = default;
};

} // namespace carrom::proto
