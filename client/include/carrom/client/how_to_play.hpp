#pragma once
// The "How to play" screen and the first-game walkthrough: the rules of each rule set in a few
// plain lines (docs/rules.md is the full reference), the controls, and the walkthrough's steps.
// web/js/how_to_play.js says the same words; tests/golden/words/words.json holds them for both.

#include "carrom/proto/types.hpp"

#include <string>
#include <vector>

namespace carrom::client {

struct HowToPlay {
    std::string title;              // "ICF rules"
    std::vector<std::string> rules; // the rule set's rules, one sentence each
    std::string foul;               // what a foul costs (also in `rules`)
};

HowToPlay how_to_play(proto::RuleSet rule_set);
// Placing, aiming, power and cancelling, the same for every rule set.
std::vector<std::string> controls_help();
// The walkthrough of a first game, one step a card: place, aim, power, what a foul costs.
std::vector<std::string> walkthrough_steps(proto::RuleSet rule_set);

} // namespace carrom::client
