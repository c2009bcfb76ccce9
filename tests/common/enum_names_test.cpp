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

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

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

// Every entry round-trips both ways, values and names are distinct, the table lists the
// enumerators 0..N-1 (every enum here counts from 0 without gaps), and to_string / parse agree.
template <class E, std::size_t N, class ToString, class Parse>
void expect_table(const enum_names::Table<E, N>& table, ToString to_string, Parse parse) {
    std::set<std::string_view> names;
    for (std::size_t i = 0; i < N; ++i) {
        const E value = static_cast<E>(i);
        const auto name = enum_names::name_of(table, value);
        ASSERT_TRUE(name.has_value()) << "enumerator " << i << " has no name";
        EXPECT_EQ(enum_names::parse(table, *name), value) << *name;
        EXPECT_EQ(to_string(value), *name);
        E parsed = static_cast<E>(N == 1 ? 0 : (i + 1) % N);
        EXPECT_TRUE(parse(*name, parsed)) << *name;
        EXPECT_EQ(parsed, value) << *name;
        EXPECT_TRUE(names.insert(*name).second) << "duplicate name " << *name;
        E unchanged = value;
        EXPECT_FALSE(parse(std::string(*name) + "x", unchanged)) << *name;
        EXPECT_EQ(unchanged, value);
    }
    EXPECT_EQ(to_string(static_cast<E>(N)), "unknown");
}

TEST(EnumNames, BodyKinds) {
    expect_table(
        kBodyKindNames, [](BodyKind k) { return to_string(k); }, &parse_body_kind);
    EXPECT_EQ(to_string(BodyKind::Black), "black");
    EXPECT_EQ(to_string(BodyKind::White), "white");
    EXPECT_EQ(to_string(BodyKind::Queen), "queen");
    EXPECT_EQ(to_string(BodyKind::Striker), "striker");
}

TEST(EnumNames, EventKinds) {
    expect_table(
        kEventKindNames, [](EventKind k) { return to_string(k); },
        [](std::string_view text, EventKind& out) {
            return enum_names::parse_into(kEventKindNames, text, out);
        });
    EXPECT_EQ(to_string(EventKind::Collision), "collision");
    EXPECT_EQ(to_string(EventKind::Cushion), "cushion");
    EXPECT_EQ(to_string(EventKind::Pocket), "pocket");
    EXPECT_EQ(to_string(EventKind::Stop), "stop");
}

TEST(EnumNames, SceneBaselines) {
    expect_table(
        kBaselineNames, [](Baseline b) { return enum_names::name_or_unknown(kBaselineNames, b); },
        [](std::string_view text, Baseline& out) {
            return enum_names::parse_into(kBaselineNames, text, out);
        });
    EXPECT_EQ(enum_names::name_of(kBaselineNames, Baseline::Bottom), "bottom");
    EXPECT_EQ(enum_names::name_of(kBaselineNames, Baseline::Top), "top");
}

TEST(EnumNames, RuleSets) {
    expect_table(
        rules::kRuleSetNames, [](rules::RuleSet r) { return rules::to_string(r); },
        &rules::parse_rule_set);
    EXPECT_EQ(rules::to_string(rules::RuleSet::Icf), "icf");
    EXPECT_EQ(rules::to_string(rules::RuleSet::Seed), "seed");
    EXPECT_EQ(rules::to_string(rules::RuleSet::Freestyle), "freestyle");
    EXPECT_EQ(rules::to_string(rules::RuleSet::DiscPool), "discpool");
}

TEST(EnumNames, SeatSides) {
    expect_table(
        rules::kSideNames, [](rules::Side s) { return rules::to_string(s); }, &rules::parse_side);
    EXPECT_EQ(rules::to_string(rules::Side::Bottom), "bottom");
    EXPECT_EQ(rules::to_string(rules::Side::Right), "right");
    EXPECT_EQ(rules::to_string(rules::Side::Top), "top");
    EXPECT_EQ(rules::to_string(rules::Side::Left), "left");
}

TEST(EnumNames, RuleCodes) {
    expect_table(
        rules::kRuleCodeNames, [](rules::RuleCode c) { return rules::to_string(c); },
        &rules::parse_rule_code);
    const std::vector<std::string_view> expected{"striker_pocketed",
                                                 "queen_before_own_coin",
                                                 "queen_not_covered",
                                                 "queen_covered",
                                                 "due_paid",
                                                 "own_last_coin_before_queen",
                                                 "opponent_last_coin",
                                                 "break_missed",
                                                 "shot_clock_expired",
                                                 "missed_turns",
                                                 "forfeit",
                                                 "board_cleared",
                                                 "colour_cleared",
                                                 "coins_exhausted",
                                                 "target_points",
                                                 "boards_played"};
    ASSERT_EQ(expected.size(), rules::kRuleCodeNames.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(rules::to_string(static_cast<rules::RuleCode>(i)), expected[i]);
    }
}

TEST(EnumNames, RuleErrorCodes) {
    expect_table(
        rules::kRuleErrorCodeNames, [](rules::RuleErrorCode c) { return rules::to_string(c); },
        [](std::string_view text, rules::RuleErrorCode& out) {
            return enum_names::parse_into(rules::kRuleErrorCodeNames, text, out);
        });
    const std::vector<std::string_view> expected{
        "invalid_seat",     "game_over",        "board_over",         "not_your_turn",
        "stale_turn",       "x_not_finite",     "x_out_of_range",     "striker_overlaps",
        "angle_not_finite", "power_not_finite", "power_out_of_range", "physics_error",
        "invalid_config",   "wrong_phase"};
    ASSERT_EQ(expected.size(), rules::kRuleErrorCodeNames.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(rules::to_string(static_cast<rules::RuleErrorCode>(i)), expected[i]);
    }
}

} // namespace
} // namespace carrom
