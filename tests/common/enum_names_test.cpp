// enum_names.hpp and the name tables of common/: every name of every enum reads back as its value,
// the enum's to_string and parse function agree with its table, and other text is refused.

#include "carrom/enum_names.hpp"

#include "carrom/body.hpp"
#include "carrom/event.hpp"
#include "carrom/rules/rule_code.hpp"
#include "carrom/rules/rule_error.hpp"
#include "carrom/rules/rule_set.hpp"
#include "carrom/rules/seat.hpp"
#include "carrom/scene.hpp"

#include "support/enum_names_check.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom {
namespace {

enum class Fruit { Apple, Pear, Plum };
constexpr enum_names::Table<Fruit, 3> kFruitNames{
    {{Fruit::Apple, "apple"}, {Fruit::Pear, "pear"}, {Fruit::Plum, "plum"}}};

TEST(EnumNames, NameOfGivesTheTablesName) {
    EXPECT_EQ(enum_names::name_of(kFruitNames, Fruit::Apple), "apple");
    EXPECT_EQ(enum_names::name_of(kFruitNames, Fruit::Plum), "plum");
    EXPECT_EQ(enum_names::name_of(kFruitNames, static_cast<Fruit>(7)), std::nullopt);
}

TEST(EnumNames, ParseIsExact) {
    EXPECT_EQ(enum_names::parse(kFruitNames, "pear"), Fruit::Pear);
    EXPECT_EQ(enum_names::parse(kFruitNames, "Pear"), std::nullopt);
    EXPECT_EQ(enum_names::parse(kFruitNames, "pear "), std::nullopt);
    EXPECT_EQ(enum_names::parse(kFruitNames, "pea"), std::nullopt);
    EXPECT_EQ(enum_names::parse(kFruitNames, ""), std::nullopt);
    EXPECT_EQ(enum_names::parse(kFruitNames, std::string_view("pear\0", 5)), std::nullopt);
}

TEST(EnumNames, NameOrUnknownNamesValuesOutsideTheTableUnknown) {
    EXPECT_EQ(enum_names::name_or_unknown(kFruitNames, Fruit::Pear), "pear");
    EXPECT_EQ(enum_names::name_or_unknown(kFruitNames, static_cast<Fruit>(3)), "unknown");
}

TEST(EnumNames, ParseIntoSetsOutOnlyForAName) {
    Fruit out = Fruit::Plum;
    EXPECT_FALSE(enum_names::parse_into(kFruitNames, "banana", out));
    EXPECT_EQ(out, Fruit::Plum);
    EXPECT_TRUE(enum_names::parse_into(kFruitNames, "apple", out));
    EXPECT_EQ(out, Fruit::Apple);
}

TEST(EnumNames, TablesAreUsableAtCompileTime) {
    static_assert(enum_names::name_of(kFruitNames, Fruit::Pear) == "pear");
    static_assert(enum_names::parse(kFruitNames, "plum") == Fruit::Plum);
    static_assert(!enum_names::parse(kFruitNames, "fig").has_value());
    SUCCEED();
}

using test::expect_table;
using test::parser_of;

TEST(EnumNames, BodyKinds) {
    expect_table(kBodyKindNames, [](BodyKind k) { return to_string(k); }, &parse_body_kind,
                 {"black", "white", "queen", "striker"});
}

TEST(EnumNames, EventKinds) {
    expect_table(kEventKindNames, [](EventKind k) { return to_string(k); },
                 parser_of(kEventKindNames), {"collision", "cushion", "pocket", "stop"});
}

TEST(EnumNames, SceneBaselines) {
    expect_table(kBaselineNames,
                 [](Baseline b) { return enum_names::name_or_unknown(kBaselineNames, b); },
                 parser_of(kBaselineNames), {"bottom", "top"});
}

TEST(EnumNames, RuleSets) {
    expect_table(rules::kRuleSetNames, [](rules::RuleSet r) { return rules::to_string(r); },
                 &rules::parse_rule_set, {"icf", "seed", "freestyle", "discpool"});
}

TEST(EnumNames, SeatSides) {
    expect_table(rules::kSideNames, [](rules::Side s) { return rules::to_string(s); },
                 &rules::parse_side, {"bottom", "right", "top", "left"});
}

TEST(EnumNames, RuleCodes) {
    expect_table(rules::kRuleCodeNames, [](rules::RuleCode c) { return rules::to_string(c); },
                 &rules::parse_rule_code,
                 {"striker_pocketed", "queen_before_own_coin", "queen_not_covered", "queen_covered",
                  "due_paid", "own_last_coin_before_queen", "opponent_last_coin", "break_missed",
                  "shot_clock_expired", "missed_turns", "forfeit", "board_cleared",
                  "colour_cleared", "coins_exhausted", "target_points", "boards_played"});
}

TEST(EnumNames, RuleErrorCodes) {
    expect_table(
        rules::kRuleErrorCodeNames, [](rules::RuleErrorCode c) { return rules::to_string(c); },
        parser_of(rules::kRuleErrorCodeNames),
        {"invalid_seat", "game_over", "board_over", "not_your_turn", "stale_turn", "x_not_finite",
         "x_out_of_range", "striker_overlaps", "angle_not_finite", "power_not_finite",
         "power_out_of_range", "physics_error", "invalid_config", "wrong_phase"});
}

} // namespace
} // namespace carrom
