#include "carrom/wasm/replay_api.h"

#include "api_error.hpp"

#include "carrom/exact_engine.hpp"
#include "carrom/rules/match.hpp"
#include "carrom/rules/rules_version.hpp"
#include "carrom/rules/state_hash.hpp"

#include <array>
#include <cstddef>
#include <optional>

namespace {

constexpr std::size_t kConfigFields = 16;
constexpr std::size_t kResultFields = 24;
constexpr std::size_t kTeamSlots = 4;

// The replayed game (see replay_api.h).
struct ReplayApiState {
    carrom::PhysicsConfig physics{};
    carrom::ExactEngine engine{physics};
    std::array<double, kConfigFields> config{};
    std::optional<carrom::rules::MatchState> state; // the next input is played on it
    std::array<double, kResultFields> result{};
    std::array<double, carrom::kCoinCount * 5> result_board{}; // as the rules returned it
    std::array<double, carrom::kCoinCount * 5> board{};        // the next input's
};

ReplayApiState& replay() {
    static ReplayApiState state;
    return state;
}

int whole(double x) {
    return static_cast<int>(x);
}

carrom::rules::RulesConfig rules_from(const std::array<double, kConfigFields>& c) {
    carrom::rules::RulesConfig r;
    r.seat_count = whole(c[0]);
    r.first_breaker = whole(c[1]);
    r.shot_clock_s = c[2];
    r.shot_clock_grace_s = c[3];
    r.missed_turns_to_lose = whole(c[4]);
    r.target_points = whole(c[5]);
    r.max_boards = whole(c[6]);
    r.queen_points = whole(c[7]);
    r.queen_points_limit = whole(c[8]);
    r.board_points_cap = whole(c[9]);
    r.break_tries = whole(c[10]);
    r.freestyle = {whole(c[11]), whole(c[12]), whole(c[13]), whole(c[14]), whole(c[15])};
    return r;
}

void write_board(std::array<double, carrom::kCoinCount * 5>& out,
                 const carrom::rules::MatchState& m) {
    out.fill(0.0);
    std::size_t i = 0;
    for (const carrom::Body& b : m.bodies) {
        if (i + 5 > out.size()) {
            break;
        }
        out[i] = b.id;
        out[i + 1] = static_cast<double>(b.kind);
        out[i + 2] = b.pos_px.x;
        out[i + 3] = b.pos_px.y;
        out[i + 4] = b.pocketed ? 1.0 : 0.0;
        i += 5;
    }
}

void write_result(ReplayApiState& s, const carrom::rules::MatchState& m) {
    std::array<double, kResultFields>& r = s.result;
    r.fill(0.0);
    r[0] = m.turn_number;
    r[1] = m.turn_seat;
    r[2] = m.board;
    r[3] = static_cast<double>(m.phase);
    for (std::size_t t = 0; t < kTeamSlots; ++t) {
        r[4 + t] = t < m.scores.size() ? m.scores[t] : 0;
        r[8 + t] = t < m.dues_owed.size() ? m.dues_owed[t] : 0;
    }
    r[12] = m.result ? m.result->winner_team.value_or(-1) : -2;
    r[13] = m.result ? static_cast<double>(m.result->reason) : -1.0;
    r[14] = !m.boards.empty() ? m.boards.back().winner_team.value_or(-1) : -1;
    r[15] = !m.boards.empty() ? m.boards.back().points : 0;
    const std::uint64_t hash = carrom::rules::hash_match_state(m);
    r[16] = static_cast<double>(hash >> 32U);
    r[17] = static_cast<double>(hash & 0xFFFFFFFFU);
    for (std::size_t seat = 0; seat < kTeamSlots; ++seat) {
        r[18 + seat] = seat < m.seats.size() ? static_cast<double>(m.seats[seat].side) : -1.0;
    }
}

} // namespace

extern "C" {

int carrom_rules_version() {
    return carrom::rules::kRulesVersion;
}

double* carrom_replay_config() {
    return replay().config.data();
}

int carrom_replay_start(int rule_set, int first_turn) {
    ReplayApiState& s = replay();
    const carrom::rules::RulesConfig config = rules_from(s.config);
    if (rule_set < 0 || rule_set > 3 || carrom::rules::validate_rules_config(config)) {
        s.state.reset();
        carrom::wasm::set_api_error("invalid_config");
        return -1;
    }
    s.state =
        carrom::rules::new_match(static_cast<carrom::rules::RuleSet>(rule_set), config, s.physics);
    s.state->turn_number = first_turn;
    write_result(s, *s.state);
    write_board(s.result_board, *s.state);
    write_board(s.board, *s.state);
    carrom::wasm::set_api_error("");
    return 0;
}

int carrom_replay_play(int kind, int seat, double x_px, double angle_rad, double power) {
    ReplayApiState& s = replay();
    if (!s.state || kind < 0 || kind > 2) {
        carrom::wasm::set_api_error("bad_input");
        return -1;
    }
    carrom::rules::PlayResult r;
    if (kind == 0) {
        r = carrom::rules::play_shot(*s.state, seat, {x_px, angle_rad, power}, s.engine);
    } else if (kind == 1) {
        r = carrom::rules::shot_clock_expired(*s.state, seat);
    } else {
        r = carrom::rules::forfeit(*s.state, seat);
    }
    if (r.error) {
        carrom::wasm::set_api_error(carrom::rules::to_string(r.error->code));
        return -1;
    }
    carrom::wasm::set_api_error("");
    write_result(s, r.state);
    write_board(s.result_board, r.state);
    s.state = std::move(r.state);
    if (s.state->phase == carrom::rules::Phase::BoardOver) {
        s.state = carrom::rules::start_next_board(*s.state);
    }
    write_board(s.board, *s.state);
    return 0;
}

const double* carrom_replay_result() {
    return replay().result.data();
}

const double* carrom_replay_board(int next) {
    return next != 0 ? replay().board.data() : replay().result_board.data();
}

} // extern "C"
