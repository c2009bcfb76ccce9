// The name tables of proto/'s enums (enum_names.hpp): each names every enumerator with its exact
// wire or file text, and to_string / parse agree with it.

#include "carrom/proto/journal.hpp"
#include "carrom/proto/match_json.hpp"
#include "carrom/proto/types.hpp"

#include "support/enum_names_check.hpp"

#include <gtest/gtest.h>

namespace carrom::proto {
namespace {

using carrom::test::expect_table;

// The wire enums' to_string and parse overloads, as callables.
constexpr auto kToString = [](auto value) { return to_string(value); };
constexpr auto kParse = [](std::string_view text, auto& out) { return parse(text, out); };

TEST(ProtoEnumNames, WireEnums) {
    expect_table(kRuleSetNames, kToString, kParse, {"icf", "seed", "freestyle", "discpool"});
    expect_table(kRoleNames, kToString, kParse, {"player", "spectator"});
    expect_table(kColourNames, kToString, kParse, {"none", "black", "white"});
    expect_table(kPhaseNames, kToString, kParse,
                 {"waiting", "aiming", "moving", "board_over", "game_over"});
    expect_table(kQueenStateNames, kToString, kParse, {"on_board", "pending", "covered", "none"});
    expect_table(kBotLevelNames, kToString, kParse, {"random", "easy", "medium", "hard"});
    expect_table(
        kEmoteNames, kToString, kParse,
        {"nice_shot", "good_game", "well_played", "thanks", "good_luck", "oops", "wow", "sorry"});
}

TEST(ProtoEnumNames, WireBaselinesAndBodyKindsAreCommonsNames) {
    expect_table(rules::kSideNames, &baseline_name, kParse, {"bottom", "right", "top", "left"});
    expect_table(kBodyKindNames, &body_kind_name, kParse, {"black", "white", "queen", "striker"});
}

TEST(ProtoEnumNames, MatchStateEnums) {
    expect_table(kMatchPhaseNames, kToString, &parse_phase,
                 {"awaiting_shot", "board_over", "game_over"});
    expect_table(kQueenStatusNames, kToString, &parse_queen_status,
                 {"on_board", "pending_cover", "covered", "out_of_play"});
}

TEST(ProtoEnumNames, JournalForfeitReasons) {
    expect_table(kForfeitReasonNames, kToString, kParse, {"left", "grace_expired"});
}

} // namespace
} // namespace carrom::proto
