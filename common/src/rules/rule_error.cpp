#include "carrom/rules/rule_error.hpp"

namespace carrom::rules {

std::string_view to_string(RuleErrorCode code) {
    return enum_names::name_or_unknown(kRuleErrorCodeNames, code);
}

} // namespace carrom::rules
