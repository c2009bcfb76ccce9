#pragma once
// Which game a match plays. Chosen per match; see docs/rules.md.

#include "carrom/enum_names.hpp"

#include <cstdint>
#include <string_view>

namespace carrom::rules {

enum class RuleSet : std::uint8_t {
    Icf,       // official carrom (International Carrom Federation laws); the default
    Seed,      // the seed game's rules with its defects fixed
    Freestyle, // any coin for points
    DiscPool,  // each side clears its own nine coins; no queen
};
inline constexpr enum_names::Table<RuleSet, 4> kRuleSetNames{{
    {RuleSet::Icf, "icf"},
    {RuleSet::Seed, "seed"},
    {RuleSet::Freestyle, "freestyle"},
    {RuleSet::DiscPool, "discpool"},
}};

// "icf", "seed", "freestyle", "discpool".
std::string_view to_string(RuleSet rule_set);
// Parses the names above; returns false (and leaves out unchanged) for anything else.
bool parse_rule_set(std::string_view text, RuleSet& out);

} // namespace carrom::rules
