#include "carrom/rules/rule_code.hpp"

namespace carrom::rules {

std::string_view to_string(RuleCode code) {
    return enum_names::name_or_unknown(kRuleCodeNames, code);
}

bool parse_rule_code(std::string_view text, RuleCode& out) {
    return enum_names::parse_into(kRuleCodeNames, text, out);
}

} // namespace carrom::rules
