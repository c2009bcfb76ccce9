#pragma once
// A match journal played back with the local exact engine (carrom-client --replay): every input
// (stroke, shot clock expiry, forfeit) is run through the rules and the engine again, as the server
// ran it, and laid out on one replay timeline. Pure and deterministic, no window: the replay view
// (client/app/replay_view.hpp) draws what this model says.
//
// The timeline: each input gets kLeadS seconds showing the board it was played on (a stroke's
// striker on its baseline, where it was placed), then the stroke's motion (a stroke's shot time
// t runs from 0 to its simulation's end), then kTailS seconds showing the board as the rules left
// it (returned pieces placed). Clock expiries and forfeits have no motion. At shot time t a stroke
// shows exactly what the server's ShotStream sent live at t: state_at(physics, trajectory, t) with
// positions and velocities quantised to 0.01 px (px/s). Aiming time is not replayed.

#include "carrom/config.hpp"
#include "carrom/proto/journal.hpp"
#include "carrom/proto/scene_json.hpp"
#include "carrom/proto/server_messages.hpp"
#include "carrom/rules/match.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

namespace carrom::client {

// One replayed input of the journal.
struct ReplayTurn {
    std::size_t entry = 0;       // index in journal.entries
    bool stroke = false;         // a stroke (else a clock expiry or a forfeit)
    int stroke_number = 0;       // strokes up to and including this one (1-based for a stroke)
    rules::MatchState before;    // the state the input was played on
    rules::MatchState result;    // as the rules returned it (before start_next_board)
    rules::ShotOutcome outcome;  // a stroke's keeps its trajectory and events
    std::string forfeit_reason;  // a forfeit's game_end reason: "left" or "forfeit"
    bool matches_journal = true; // the replayed state hash equals the journal's
    double start_s = 0.0;        // replay timeline: the lead starts
    double motion_s = 0.0;       // the motion starts (shot time 0)
    double rest_s = 0.0;         // the motion ends, the rules' board shows
    double end_s = 0.0;          // the next input's lead starts
};

class ReplayModel {
public:
    static constexpr double kLeadS = 0.6;
    static constexpr double kTailS = 0.8;
    static constexpr double kMinSpeed = 0.25;
    static constexpr double kMaxSpeed = 4.0;
    static constexpr std::array<double, 5> kSpeeds{0.25, 0.5, 1.0, 2.0, 4.0};

    // A journal this build can replay, or why not: check_versions' version_mismatch, the head's
    // bad_journal, or an input the rules refuse (bad_journal, path "entries[N]").
    static std::variant<ReplayModel, proto::Error> load(const proto::MatchJournal& journal);
    // decode_journal_text, then load.
    static std::variant<ReplayModel, proto::Error> load_text(std::string_view text);

    const proto::MatchCreated& created() const { return created_; }
    const std::vector<ReplayTurn>& turns() const { return turns_; }
    int stroke_count() const { return stroke_count_; }
    // Inputs whose replayed state differs from what the journal recorded.
    int mismatches() const { return mismatches_; }

    // Playback. Time only moves in advance(): wall seconds times the speed, while playing.
    double time_s() const { return time_s_; }
    double duration_s() const { return duration_s_; }
    bool playing() const { return playing_; }
    bool finished() const { return time_s_ >= duration_s_; }
    double speed() const { return speed_; }
    void play();
    void pause() { playing_ = false; }
    void toggle_play();
    void set_speed(double speed); // clamped to [kMinSpeed, kMaxSpeed]
    void faster();                // the next speed of kSpeeds
    void slower();                // the previous speed of kSpeeds
    void advance(double wall_s);  // pauses at the end
    void seek(double time_s);     // clamped to [0, duration]
    void restart();               // time 0, playing
    // Jump to the start of the next / previous (or, after its lead, the current) input's lead.
    void next_turn();
    void previous_turn();

    // The input shown at time t (the last one once the replay ends); turns() must not be empty.
    std::size_t turn_at(double time_s) const;
    std::size_t current_turn() const { return turn_at(time_s_); }
    // Strokes played so far, counting the current one once its motion started ("Stroke 5 / 37").
    int stroke_number() const;
    // Inputs (strokes, clock expiries, forfeits) played so far, counting the current one once its
    // lead is over ("Turn 5 / 40" of turns().size()); all of them at the end.
    int turn_number() const;
    // The rules' state shown at time t: the input's `before` until its motion ends, then its
    // `result` (the state after the last input once the journal is over, without a turn).
    const rules::MatchState& state_at_time(double time_s) const;
    // Every body at time t (the 19 pieces, then the striker), quantised as the server's stream.
    std::vector<Body> bodies_at(double time_s) const;
    std::vector<Body> bodies() const { return bodies_at(time_s_); }
    // A stroke's bodies at shot time t (0 .. its simulation's end), quantised: what the server's
    // ShotStream sent at t. turn must be a stroke.
    std::vector<Body> bodies_in_stroke(std::size_t turn, double shot_t_s) const;
    // Shot time within the current stroke's motion, if t is in one.
    std::optional<double> shot_time_at(double time_s) const;

    // The state after the last input, start_next_board applied, as the server held it.
    const rules::MatchState& final_state() const { return final_; }

    // What a spectator's client was told about the state shown at time t: a room state (code
    // "REPLAY" unless the journal names a room, spectator, no shot clock), and after an input's
    // motion the shot result and the rule events (fouls, queen, dues, board and game end).
    proto::RoomState room_state_at(double time_s) const;
    std::vector<proto::ServerMessage> outcome_messages(std::size_t turn) const;

private:
    ReplayModel() = default;

    proto::MatchCreated created_;
    std::vector<ReplayTurn> turns_;
    rules::MatchState initial_;
    rules::MatchState final_;
    int stroke_count_ = 0;
    int mismatches_ = 0;
    double duration_s_ = 0.0;
    double time_s_ = 0.0;
    double speed_ = 1.0;
    bool playing_ = true;
};

} // namespace carrom::client
