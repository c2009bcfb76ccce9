#pragma once
// Journals for tests: games played the way the server plays them (rules::play_shot with the
// trajectory recorded, start_next_board after a board ends), with seeded shots aimed at pieces
// on the board, and every input journaled through stroke_entry and friends.

#include "carrom/proto/journal.hpp"
#include "carrom/proto/journal_replay.hpp"
#include "carrom/rules/match.hpp"
#include "carrom/rules/state_hash.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <utility>

namespace carrom::proto::test {

// A double in [lo, hi) from the generator's raw output (whose sequence the standard fixes).
inline double draw(std::mt19937_64& rng, double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11U) * 0x1.0p-53;
}

inline MatchCreated make_created(rules::RuleSet rule_set, rules::RulesConfig config = {},
                                 std::string id = "m-0001") {
    MatchCreated c;
    c.match_id = std::move(id);
    c.room_code = "ABCDEF";
    c.rule_set = rule_set;
    c.rules = config;
    c.seats = {JournalSeat{"ann", false}, JournalSeat{"Bot (medium)", true}};
    c.versions.server = "0.1.0";
    c.time_ms = 1700000000000;
    return c;
}

// Rules that end a random game quickly: few points to win, few boards.
inline rules::RulesConfig short_game() {
    rules::RulesConfig config;
    config.target_points = 5;
    config.max_boards = 2;
    config.freestyle.target = 100;
    return config;
}

// A legal shot for seat: a random position on its baseline, aimed at a random piece on the
// board, with a random power.
inline Shot aimed_shot(const rules::MatchState& m, int seat, std::mt19937_64& rng) {
    const PhysicsConfig& physics = m.physics;
    const rules::Side side = m.seats[static_cast<std::size_t>(seat)].side;
    std::vector<Vec2> targets;
    for (const Body& body : m.bodies) {
        if (!body.pocketed) {
            targets.push_back(body.pos_px);
        }
    }
    for (int attempt = 0; attempt < 200; ++attempt) {
        Shot shot{draw(rng, baseline_x_min(physics), baseline_x_max(physics)), 0.0,
                  draw(rng, 4.0, physics.max_power)};
        const Vec2 from = rules::striker_for(physics, side, shot).pos_px;
        const Vec2 to = targets.empty() ? physics.centre()
                                        : targets[static_cast<std::size_t>(rng() % targets.size())];
        shot.angle_rad = std::atan2(to.y - from.y, to.x - from.x);
        if (!rules::check_placement(m, seat, shot)) {
            return shot;
        }
    }
    return Shot{physics.centre().x, 0.0, 1.0};
}

// Plays one game as the server does and journals every input.
class JournalRecorder {
public:
    explicit JournalRecorder(MatchCreated created)
        : state_(initial_state(created)), engine_(std::make_unique<ExactEngine>(created.physics)) {
        journal_.created = std::move(created);
        time_ms_ = journal_.created.time_ms;
    }

    const MatchJournal& journal() const { return journal_; }
    const rules::MatchState& state() const { return state_; }
    bool over() const { return state_.phase == rules::Phase::GameOver; }

    rules::PlayResult stroke(const Shot& shot) {
        rules::PlayOptions options;
        options.record_trajectory = true; // as the server plays: the hash must not depend on it
        rules::PlayResult r = rules::play_shot(state_, state_.turn_seat, shot, *engine_, options);
        if (!r.error) {
            add(stroke_entry(tick(), r));
            advance(r);
        }
        return r;
    }
    void clock_expired() {
        const rules::PlayResult r = rules::shot_clock_expired(state_, state_.turn_seat);
        add(clock_expired_entry(tick(), r));
        advance(r);
    }
    void forfeit(int seat, ForfeitReason reason) {
        const rules::PlayResult r = rules::forfeit(state_, seat);
        add(forfeit_entry(tick(), r, reason));
        advance(r);
    }
    void member(JournalEvent event) { add(JournalEntry{tick(), std::move(event)}); }

private:
    std::int64_t tick() { return time_ms_ += 1500; }
    void add(JournalEntry entry) { journal_.entries.push_back(std::move(entry)); }
    void advance(const rules::PlayResult& r) {
        state_ = r.state;
        if (state_.phase == rules::Phase::BoardOver) {
            state_ = rules::start_next_board(state_);
        }
    }

    MatchJournal journal_;
    rules::MatchState state_;
    std::unique_ptr<ExactEngine> engine_; // (held by pointer: the recorder moves)
    std::int64_t time_ms_ = 0;
};

// A seeded game: aimed strokes, now and then a clock expiry or a dropped and returned seat; a
// game still running after max_inputs strokes and expiries ends with seat 1's forfeit.
inline JournalRecorder random_game(rules::RuleSet rule_set, std::uint64_t seed,
                                   int max_inputs = 300) {
    JournalRecorder recorder(make_created(rule_set, short_game()));
    std::mt19937_64 rng(seed);
    for (int i = 0; i < max_inputs && !recorder.over(); ++i) {
        const auto roll = rng() % 100;
        if (roll < 4) {
            recorder.clock_expired();
            continue;
        }
        if (roll < 7) {
            const int seat = static_cast<int>(rng() % 2);
            recorder.member(SeatDroppedEntry{seat});
            recorder.member(SeatReturnedEntry{seat});
        }
        recorder.stroke(aimed_shot(recorder.state(), recorder.state().turn_seat, rng));
    }
    if (!recorder.over()) {
        recorder.forfeit(1, ForfeitReason::GraceExpired);
    }
    return recorder;
}

} // namespace carrom::proto::test
