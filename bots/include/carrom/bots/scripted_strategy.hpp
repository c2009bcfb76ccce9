#pragma once
// "scripted": plays the shots of a script in order and starts again at the end. A shot whose
// striker position is blocked by a piece is moved to the nearest legal position on the baseline
// (angle and power kept), so a script written for one board still plays on another.
//
// Script format (see docs/bots.md): JSON lines, one shot per line, {"x": px, "angle": rad,
// "power": 0..25}; blank lines and lines starting with '#' are skipped.

#include "carrom/bots/strategy.hpp"

#include <string_view>
#include <variant>
#include <vector>

namespace carrom::bots {

// The shots of a script, or one sentence naming the first bad line ("line 3: ...").
std::variant<std::vector<Shot>, std::string> parse_script(std::string_view text);

class ScriptedStrategy final : public Strategy {
public:
    explicit ScriptedStrategy(std::vector<Shot> shots); // precondition: not empty
    std::string_view name() const override { return "scripted"; }
    Shot choose_shot(const rules::MatchState& state, int seat,
                     const DecisionBudget& budget) override;
    void shot_refused() override { ++nudge_; }
    std::size_t next_index() const { return next_; }

private:
    std::vector<Shot> shots_;
    std::size_t next_ = 0;
    int nudge_ = 0; // refusals of the current shot: each moves the striker a little further
};

} // namespace carrom::bots
