#include "carrom/rules/rule_set.hpp"

#include <array>
#include <utility>

namespace carrom::rules {
namespace {

constexpr std::array<std::pair<RuleSet, std::string_view>, 4> kRuleSetNames{{
    {RuleSet::Icf, "icf"},
    {RuleSet::Seed, "seed"},
    {RuleSet::Freestyle, "freestyle"},
    {RuleSet::DiscPool, "discpool"},
}};

} // namespace

std::string_view to_string(RuleSet rule_set) {
    for (const auto& [value, name] : kRuleSetNames) {
        if (value == rule_set) {
            return name;
        }
    }
    return "unknown";
}

bool parse_rule_set(std::string_view text, RuleSet& out) {
    for (const auto& [value, name] : kRuleSetNames) {
        if (name == text) {
            out = value;
            return true;
        }
    }
    return false;
}

} // namespace carrom::rules
