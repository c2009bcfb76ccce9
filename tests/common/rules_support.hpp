#pragma once
// Helpers for the rules tests: matches with the clock off, strokes judged from a chosen set of
// pocketed pieces (no physics), and scenes set up for real strokes through the exact engine.
// In the standard layout odd ids are black, even ids 1..18 white, 0 the queen.

#include "carrom/rules/match.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

namespace carrom::rules::test {

// Coin ids of the standard layout: even ids are white, odd ids black (0 is the queen).
inline constexpr int kWhite = 2;
inline constexpr int kWhite2 = 4;
inline constexpr int kBlack = 1;
inline constexpr int kBlack2 = 3;

inline RulesConfig no_clock() {
    RulesConfig config;
    config.shot_clock_s = 0.0;
    return config;
}

inline MatchState match(RuleSet rule_set, RulesConfig config = no_clock()) {
    return new_match(rule_set, config, PhysicsConfig{});
}

// A match past the break (icf), so a stroke that touches nothing is an ordinary miss.
inline MatchState broken(RuleSet rule_set, RulesConfig config = no_clock()) {
    MatchState m = match(rule_set, config);
    m.break_done = true;
    return m;
}

inline std::vector<int> ids_of(const MatchState& m, BodyKind kind, bool on_board = true) {
    std::vector<int> ids;
    for (const Body& body : m.bodies) {
        if (body.kind == kind && body.pocketed != on_board) {
            ids.push_back(body.id);
        }
    }
    return ids;
}

// Takes a piece off the board before the test's stroke, as if seat had pocketed it.
inline void pre_pocket(MatchState& m, int id, int seat) {
    Body& body = m.bodies[static_cast<std::size_t>(id)];
    body.pocketed = true;
    m.pocketed.push_back(PocketedPiece{id, body.kind, seat, m.turn_number});
}

// Physics in which exactly `ids` (and the striker, when striker) went into pockets.
inline StrokePhysics pocketing(const MatchState& m, std::vector<int> ids, bool striker = false) {
    StrokePhysics physics;
    physics.bodies = m.bodies;
    for (int id : ids) {
        physics.bodies[static_cast<std::size_t>(id)].pocketed = true;
    }
    physics.pocket_order = ids;
    physics.striker_pocketed = striker;
    physics.striker_touched_coin = true;
    return physics;
}

// The turn seat's stroke that pockets exactly ids.
inline StrokeResult stroke(const MatchState& m, std::vector<int> ids, bool striker = false) {
    return judge_stroke(m, m.turn_seat, Shot{300.0, -1.0, 10.0}, pocketing(m, ids, striker));
}

inline bool overlaps_any(const MatchState& m) {
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
        for (std::size_t j = i + 1; j < m.bodies.size(); ++j) {
            const Body& a = m.bodies[i];
            const Body& b = m.bodies[j];
            if (a.pocketed || b.pocketed) {
                continue;
            }
            const double reach = m.physics.radius(a.kind) + m.physics.radius(b.kind);
            if (length(a.pos_px - b.pos_px) < reach - 1e-9) {
                std::printf("overlap %d %d by %.3g px\n", a.id, b.id,
                            reach - length(a.pos_px - b.pos_px));
                return true;
            }
        }
    }
    return false;
}

// Real strokes through the exact engine. From the bottom baseline at x = 487 towards the
// bottom-right pocket (543, 543), a piece at kNearPocket is hit head on: at power 1 it drops
// and the striker stays on the board; at power 3 both drop. Mirrored (y -> 600 - y) for the top.
inline constexpr Vec2 kNearPocket{518.5, 533.0};
inline constexpr Vec2 kNearPocketTop{518.5, 67.0};
inline constexpr double kSoft = 1.0;
inline constexpr double kHard = 3.0;

inline Shot towards_pocket(const MatchState& m, int seat, double power) {
    const bool bottom = m.seats[static_cast<std::size_t>(seat)].side == Side::Bottom;
    const double dy = bottom ? 543.0 - 520.0 : 57.0 - 80.0;
    return Shot{487.0, std::atan2(dy, 543.0 - 487.0), power};
}

// A shot that touches nothing: from the left end of the baseline along it, softly.
inline Shot miss() {
    return Shot{113.0, 0.0, 0.5};
}

inline void put(MatchState& m, int id, Vec2 pos) {
    m.bodies[static_cast<std::size_t>(id)].pos_px = pos;
}

inline PlayResult play(const MatchState& m, const Shot& shot) {
    ExactEngine engine(m.physics);
    return play_shot(m, m.turn_seat, shot, engine);
}

} // namespace carrom::rules::test

namespace carrom::rules::test {
inline bool contains_id(const std::vector<int>& ids, int id) {
    for (int x : ids) {
        if (x == id) {
            return true;
        }
    }
    return false;
}
} // namespace carrom::rules::test
