#include "carrom/rules/state_hash.hpp"
#include "carrom/double_bits.hpp"

#include <optional>
#include <vector>

namespace carrom::rules {
namespace {

// FNV-1a 64 over little-endian words, as ResultHash does.
class Fnv {
public:
    void word(std::uint64_t w) {
        for (int byte = 0; byte < 8; ++byte) {
            value_ ^= (w >> (8 * byte)) & 0xFFU;
            value_ *= 1099511628211ULL; // the FNV-1a 64-bit prime
        }
    }
    void integer(int x) { word(static_cast<std::uint64_t>(static_cast<std::uint32_t>(x))); }
    void number(double x) { word(double_bits(x)); }
    void flag(bool b) { integer(b ? 1 : 0); }
    void vec(Vec2 v) {
        number(v.x);
        number(v.y);
    }
    // A length first, so that [1, 2] + [] and [1] + [2] differ.
    void ints(const std::vector<int>& values) {
        integer(static_cast<int>(values.size()));
        for (int v : values) {
            integer(v);
        }
    }
    // -1 marks an empty optional (teams are never negative).
    void team(const std::optional<int>& t) { integer(t.value_or(-1)); }
    std::uint64_t value() const { return value_; }

private:
    std::uint64_t value_ = 1469598103934665603ULL; // the FNV-1a 64-bit offset basis
};

void add_rules(Fnv& h, const RulesConfig& c) {
    h.integer(c.seat_count);
    h.integer(c.first_breaker);
    h.number(c.shot_clock_s);
    h.number(c.shot_clock_grace_s);
    h.integer(c.missed_turns_to_lose);
    h.integer(c.target_points);
    h.integer(c.max_boards);
    h.integer(c.queen_points);
    h.integer(c.queen_points_limit);
    h.integer(c.board_points_cap);
    h.integer(c.break_tries);
    h.integer(c.freestyle.white);
    h.integer(c.freestyle.black);
    h.integer(c.freestyle.queen);
    h.integer(c.freestyle.striker_penalty);
    h.integer(c.freestyle.target);
}

void add_physics(Fnv& h, const PhysicsConfig& c) {
    for (double x :
         {c.board_size_px, c.frame_px, c.coin_radius_px, c.striker_radius_px, c.coin_mass,
          c.striker_mass, c.damping_per_s, c.stop_speed_px_s, c.cushion_restitution,
          c.disc_restitution, c.restitution_floor_px_s, c.pocket_radius_px, c.max_power,
          c.power_to_speed, c.baseline_offset_px, c.baseline_end_margin_px}) {
        h.number(x);
    }
    h.integer(c.max_events);
}

void add_board(Fnv& h, const MatchState& s) {
    h.integer(static_cast<int>(s.seats.size()));
    for (const Seat& seat : s.seats) {
        h.integer(seat.index);
        h.integer(static_cast<int>(seat.side));
        h.integer(seat.team);
        h.integer(seat.partner);
    }
    h.integer(static_cast<int>(s.bodies.size()));
    for (const Body& b : s.bodies) {
        h.integer(b.id);
        h.integer(static_cast<int>(b.kind));
        h.vec(b.pos_px);
        h.vec(b.vel_px_s);
        h.flag(b.pocketed);
    }
    h.integer(static_cast<int>(s.pocketed.size()));
    for (const PocketedPiece& p : s.pocketed) {
        h.integer(p.id);
        h.integer(static_cast<int>(p.kind));
        h.integer(p.seat);
        h.integer(p.turn_number);
    }
}

void add_results(Fnv& h, const MatchState& s) {
    h.integer(static_cast<int>(s.boards.size()));
    for (const BoardResult& b : s.boards) {
        h.integer(b.board);
        h.team(b.winner_team);
        h.integer(b.points);
        h.integer(static_cast<int>(b.reason));
    }
    h.flag(s.result.has_value());
    if (s.result) {
        h.team(s.result->winner_team);
        h.integer(static_cast<int>(s.result->reason));
    }
}

} // namespace

std::uint64_t hash_match_state(const MatchState& state) {
    Fnv h;
    h.integer(static_cast<int>(state.rule_set));
    add_rules(h, state.config);
    add_physics(h, state.physics);
    add_board(h, state);
    h.ints(state.scores);
    h.ints(state.dues_owed);
    h.ints(state.missed_turns);
    h.integer(state.board);
    h.integer(state.breaker);
    h.integer(state.turn_seat);
    h.integer(state.turn_number);
    h.integer(state.strokes_this_board);
    h.integer(state.break_tries);
    h.flag(state.break_done);
    h.integer(static_cast<int>(state.queen.status));
    h.integer(state.queen.seat);
    h.integer(static_cast<int>(state.phase));
    add_results(h, state);
    return h.value();
}

} // namespace carrom::rules
