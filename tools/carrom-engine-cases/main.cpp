// carrom-engine-cases: the determinism test's cases and the native build's answers. Writes one
// JSON object per line to stdout: the standard break (full power straight up from the middle of
// the bottom baseline), then COUNT random shots from real positions: the boards of a game played
// by the rules (rules::play_shot) with seeded random shots, each made legal by
// rules::nearest_legal_shot, boards and games started anew as they end. Each case is simulated
// through the page's C API (wasm/include/carrom/wasm/engine_api.h) built natively, so
// tests/wasm/determinism_test.mjs runs the same calls on the WebAssembly build and compares.
//
//   carrom-engine-cases [COUNT] [SEED]     (defaults 1000 and 1)
//
// A line: {"game": G, "seat": S, "side": S, "shot": [x, angle, power], "bodies": [[id, kind, x, y,
// pocketed], ...], "hash": "16 hex digits" (the ResultHash), "events": N, "end": T,
// "final": [[id, x, y, pocketed], ...]}; the first line of each game (G = 0, 1, ...; -1 for the
// standard break) also has "rules": its RulesConfig in carrom_replay_config's order (icf, first
// turn 0), so that the game can be replayed through the rules. Doubles in %.17g, which
// JSON.parse reads back exactly.

#include "carrom/exact_engine.hpp"
#include "carrom/rules/match.hpp"
#include "carrom/rules/placement.hpp"
#include "carrom/scene.hpp"
#include "carrom/wasm/engine_api.h"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <span>
#include <string>

namespace {

void print_double(double x) {
    std::printf("%.17g", x);
}

// One case: the pieces into carrom_scene, simulated, the inputs and outputs printed.
// Which game and seat a case comes from; rules: set on a game's first case.
struct CaseTag {
    long game = -1;
    int seat = 0;
    const carrom::rules::RulesConfig* rules = nullptr;
};

void print_rules(const carrom::rules::RulesConfig& r) {
    std::printf(", \"rules\": [%d, %d, ", r.seat_count, r.first_breaker);
    print_double(r.shot_clock_s);
    std::printf(", ");
    print_double(r.shot_clock_grace_s);
    std::printf(", %d, %d, %d, %d, %d, %d, %d, %d, %d, %d, %d, %d]", r.missed_turns_to_lose,
                r.target_points, r.max_boards, r.queen_points, r.queen_points_limit,
                r.board_points_cap, r.break_tries, r.freestyle.white, r.freestyle.black,
                r.freestyle.queen, r.freestyle.striker_penalty, r.freestyle.target);
}

bool write_case(std::span<const carrom::Body> pieces, carrom::rules::Side side,
                const carrom::Shot& shot, const CaseTag& tag) {
    double* scene = carrom_scene();
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const carrom::Body& b = pieces[i];
        double* r = scene + 5 * i;
        r[0] = b.id;
        r[1] = static_cast<double>(b.kind);
        r[2] = b.pos_px.x;
        r[3] = b.pos_px.y;
        r[4] = b.pocketed ? 1.0 : 0.0;
    }
    const int side_index = static_cast<int>(side);
    if (carrom_simulate(static_cast<int>(pieces.size()), side_index, shot.x_px, shot.angle_rad,
                        shot.power) != 0) {
        std::fprintf(stderr, "carrom-engine-cases: the engine refused a case: %s\n",
                     carrom_error());
        return false;
    }
    std::printf("{\"game\": %ld, \"seat\": %d", tag.game, tag.seat);
    if (tag.rules != nullptr) {
        print_rules(*tag.rules);
    }
    std::printf(", \"side\": %d, \"shot\": [", side_index);
    print_double(shot.x_px);
    std::printf(", ");
    print_double(shot.angle_rad);
    std::printf(", ");
    print_double(shot.power);
    std::printf("], \"bodies\": [");
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const double* r = scene + 5 * i;
        std::printf("%s[%d, %d, ", i > 0 ? ", " : "", static_cast<int>(r[0]),
                    static_cast<int>(r[1]));
        print_double(r[2]);
        std::printf(", ");
        print_double(r[3]);
        std::printf(", %d]", r[4] != 0.0 ? 1 : 0);
    }
    const std::uint64_t hash =
        (std::uint64_t{carrom_result_hash_high()} << 32U) | std::uint64_t{carrom_result_hash_low()};
    std::printf("], \"hash\": \"%016" PRIx64 "\", \"events\": %d, \"end\": ", hash,
                carrom_event_count());
    print_double(carrom_end_time_s());
    std::printf(", \"final\": [");
    const double* final_records = carrom_final();
    for (int i = 0; i < carrom_body_count(); ++i) {
        const double* r = final_records + 7 * i;
        std::printf("%s[%d, ", i > 0 ? ", " : "", static_cast<int>(r[0]));
        print_double(r[2]);
        std::printf(", ");
        print_double(r[3]);
        std::printf(", %d]", r[6] != 0.0 ? 1 : 0);
    }
    std::printf("]}\n");
    return true;
}

} // namespace

int main(int argc, char** argv) {
    const long count = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 1000;
    const auto seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1ULL;
    if (count < 0 || count > 1000000) {
        std::fprintf(stderr, "carrom-engine-cases: COUNT must be 0..1000000\n");
        return 2;
    }
    const carrom::PhysicsConfig physics{};
    const carrom::rules::RulesConfig rules_config{};
    const auto fresh = [&] {
        return carrom::rules::new_match(carrom::rules::RuleSet::Icf, rules_config, physics);
    };
    carrom::rules::MatchState state = fresh();
    const carrom::Shot standard_break{physics.centre().x, -std::numbers::pi / 2.0,
                                      physics.max_power};
    if (!write_case(state.bodies, carrom::rules::Side::Bottom, standard_break, {})) {
        return 1;
    }
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    carrom::ExactEngine engine(physics);
    long game = 0;
    bool new_game = true;
    for (long i = 0; i < count; ++i) {
        const int seat = state.turn_seat;
        const auto side = state.seats[static_cast<std::size_t>(seat)].side;
        // Along the baseline; towards the far half of the board (the side's "up" +- 80 degrees).
        const double x =
            carrom::baseline_x_min(physics) +
            unit(random) * (carrom::baseline_x_max(physics) - carrom::baseline_x_min(physics));
        const double up = -std::numbers::pi / 2.0 - std::numbers::pi / 2.0 * static_cast<int>(side);
        const double angle = up + (unit(random) - 0.5) * (160.0 / 180.0) * std::numbers::pi;
        const double power = (0.1 + 0.9 * unit(random)) * physics.max_power;
        const auto shot = carrom::rules::nearest_legal_shot(state, seat, {x, angle, power});
        const CaseTag tag{game, seat, new_game ? &rules_config : nullptr};
        new_game = false;
        if (!shot || !write_case(state.bodies, side, *shot, tag)) {
            return 1;
        }
        carrom::rules::PlayResult played = carrom::rules::play_shot(state, seat, *shot, engine);
        if (played.error) {
            std::fprintf(stderr, "carrom-engine-cases: the rules refused a shot: %s\n",
                         played.error->message.c_str());
            return 1;
        }
        state = std::move(played.state);
        if (state.phase == carrom::rules::Phase::BoardOver) {
            state = carrom::rules::start_next_board(state);
        } else if (state.phase == carrom::rules::Phase::GameOver) {
            state = fresh();
            ++game;
            new_game = true;
        }
    }
    return 0;
}
