#include "carrom/rules/rule_set.hpp"

namespace carrom::rules {

std::string_view to_string(RuleSet rule_set) {
    return enum_names::name_or_unknown(kRuleSetNames, rule_set);
}

bool parse_rule_set(std::string_view text, RuleSet& out) {
    return enum_names::parse_into(kRuleSetNames, text, out);
}

} // namespace carrom::rules
