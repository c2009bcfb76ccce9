#pragma once
// A bot's brain: given the match between strokes, choose the next shot. Strategies see only the
// rules' MatchState (plain data), so the same strategy plays in carrom-bot over the network, in
// tests, or inside the server (issue 7's search strategies implement this same interface).

#include "carrom/proto/types.hpp"
#include "carrom/rules/match_state.hpp"
#include "carrom/scene.hpp"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace carrom::bots {

// How much a strategy may spend on one decision. A strategy stops searching at whichever limit
// it reaches first; a cheap strategy ignores both.
struct DecisionBudget {
    std::chrono::milliseconds time{300}; // wall time for one choose_shot
    int max_candidates = 1 << 20;        // simulated candidate shots
};

class Strategy {
public:
    virtual ~Strategy() = default;
    // Stable name, as on the command line ("random", "scripted", ...).
    virtual std::string_view name() const = 0;
    // The shot for `seat`, which is to play in `state` (phase AwaitingShot, turn_seat == seat).
    // Should be legal (check_placement finds nothing) whenever a legal shot exists.
    virtual Shot choose_shot(const rules::MatchState& state, int seat,
                             const DecisionBudget& budget) = 0;
    // The server refused the shot just chosen (e.g. illegal_placement after a state mismatch):
    // the next choose_shot for the same state should differ. Default: nothing to learn.
    virtual void shot_refused() {}

    // Totals over every decision so far, for search strategies (0 for the others): candidate
    // shots simulated and wall time spent choosing, s.
    struct SearchTotals {
        std::int64_t candidates = 0;
        double seconds = 0.0;
    };
    virtual SearchTotals search_totals() const { return {}; }
};

struct StrategyOptions {
    std::string name = "random"; // "random", "scripted", "sampling", "greedy"
    std::uint64_t seed = 1;
    std::string level = "hard"; // "greedy": perfect, hard, medium or easy (skill.hpp)
    std::vector<Shot> script;   // "scripted": shots in order, repeated from the start
};

// Makes the named strategy, or one sentence saying why it cannot.
std::variant<std::unique_ptr<Strategy>, std::string> make_strategy(const StrategyOptions& options);
// The names make_strategy knows.
std::vector<std::string> strategy_names();
// The strategy of a bot level of the protocol, as the server's bots play it: random, or greedy
// at the easy, medium or hard skill level.
std::unique_ptr<Strategy> make_level_strategy(proto::BotLevel level, std::uint64_t seed);

} // namespace carrom::bots
