#pragma once
// The rules engine: a match state plus a stroke in, the new state plus the outcome out.
// Pure and deterministic: no clocks (callers pass elapsed time), no I/O, no global state.
// Functions that take a MatchState never modify it; on error the caller's state is unchanged.
//
// Typical use (a server):
//   MatchState m = new_match(RuleSet::Icf, rules_config, physics_config);
//   ExactEngine engine(m.physics);
//   PlayResult r = play_shot(m, seat, shot, engine);   // r.error set: reject the input
//   if (!r.error) m = r.state;                         // broadcast r.outcome
//   if (m.phase == Phase::BoardOver) m = start_next_board(m);

#include "carrom/exact_engine.hpp"
#include "carrom/rules/match_state.hpp"
#include "carrom/rules/placement.hpp"
#include "carrom/rules/rule_code.hpp"
#include "carrom/rules/rule_error.hpp"
#include "carrom/rules/rule_set.hpp"
#include "carrom/rules/rules_config.hpp"
#include "carrom/rules/seat.hpp"
#include "carrom/rules/shot_outcome.hpp"
#include "carrom/scene.hpp"

#include <optional>
#include <vector>

namespace carrom::rules {

// A new match at the start of board 1: standard layout, scores zero, first_breaker to shoot.
// Preconditions: validate_rules_config(rules) and validate_config(physics) found nothing.
MatchState new_match(RuleSet rule_set, const RulesConfig& rules, const PhysicsConfig& physics);

// Sets up the next board after a BoardOver: standard layout, the break passes to the next seat.
// Returns the state unchanged unless phase == BoardOver.
MatchState start_next_board(const MatchState& state);

// Whether seat may play now: InvalidSeat, GameOver, BoardOver or NotYourTurn, else nothing.
// turn_number: the turn an input names, when the caller has one (a client's aim or shoot); another
// than state.turn_number is StaleTurn (checked last). The one turn check: play_shot and
// shot_clock_expired use it, and the server's room maps its codes to wire errors.
std::optional<RuleError> check_turn(const MatchState& state, int seat,
                                    std::optional<int> turn_number = std::nullopt);

struct StrokeResult {
    MatchState state;    // the state after the stroke
    ShotOutcome outcome; //
};

struct PlayResult {
    std::optional<RuleError> error; // set: nothing happened, state is a copy of the input
    MatchState state;
    ShotOutcome outcome;
};

struct PlayOptions {
    bool record_trajectory = false; // fill outcome.physics.trajectory (for animating the stroke)
};

// Plays a stroke: check_turn, check_placement, the physics (engine must have been built with
// state.physics), then judge_stroke. Error codes are those of check_turn and check_placement,
// plus "physics_error" if the engine rejects the scene.
PlayResult play_shot(const MatchState& state, int seat, const Shot& shot, ExactEngine& engine,
                     const PlayOptions& options = {});

// What the physics did in a stroke, in the form the rules read it.
struct StrokePhysics {
    // Every piece (ids 0..18) after the stroke; extra bodies (the striker) are ignored.
    std::vector<Body> bodies;
    std::vector<int> pocket_order;    // ids in the order they were pocketed (may include 19)
    bool striker_pocketed = false;    //
    bool striker_touched_coin = true; // the striker hit at least one piece (the icf break)
};

// The rules part of a stroke, separated from the physics so that every rule can be tested
// exactly: pieces that were on the board in state and are pocketed in physics.bodies are this
// stroke's pocketed pieces. Preconditions: check_turn(state, seat) found nothing, and physics
// keeps every piece that was pocketed before pocketed.
StrokeResult judge_stroke(const MatchState& state, int seat, const Shot& shot,
                          const StrokePhysics& physics);
StrokePhysics stroke_physics_from(const SimResult& result);

// True when the clock is on and elapsed_s exceeds shot_clock_s + shot_clock_grace_s.
bool shot_clock_ran_out(const MatchState& state, double elapsed_s);

// The seat's clock ran out: the turn passes (an icf/seed/freestyle queen awaiting cover by it
// comes back); missed_turns_to_lose expiries in a row by one seat lose the game for its team.
// Errors as check_turn.
PlayResult shot_clock_expired(const MatchState& state, int seat);

// The seat gives up (or disconnected for good): its team loses. Errors: "invalid_seat",
// "game_over". Allowed in any phase before the game is over, on anyone's turn.
PlayResult forfeit(const MatchState& state, int seat);

} // namespace carrom::rules
