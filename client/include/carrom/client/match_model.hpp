#pragma once
// Everything the client knows about its match, built only from server messages: the HUD's view
// (match_view.hpp: seats, scores, turn, shot clock, queen and dues), the board to draw (through
// the playout clock and the interpolation buffer), sound cues (sound_cue_schedule.hpp) and short
// messages for the player; and the glue to the own stroke's prediction (shot_prediction.hpp).
//
// Snapshot and event times are seconds since the start of their shot (proto), so each shot's
// times are placed on one continuous timeline (shot_timeline.hpp): the first snapshot of a turn
// starts where the local clock (less the base network transit) is when it arrives. Physics
// events for a turn whose first snapshot has not arrived yet wait for it.

#include "carrom/client/coins_left.hpp"
#include "carrom/client/emote_board.hpp"
#include "carrom/client/hud_log.hpp"
#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/match_view.hpp"
#include "carrom/client/playout_clock.hpp"
#include "carrom/client/server_clock.hpp"
#include "carrom/client/shot_prediction.hpp"
#include "carrom/client/shot_timeline.hpp"
#include "carrom/client/snapshot.hpp"
#include "carrom/client/sound_cue_schedule.hpp"
#include "carrom/config.hpp"
#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/server_messages.hpp"
#include "carrom/rules/seat.hpp"

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace carrom::client {

class MatchModel {
public:
    explicit MatchModel(const PhysicsConfig& physics, const PlayoutConfig& playout = {},
                        const InterpolationConfig& interpolation = {});

    void handle(const proto::ServerMessage& message, double local_s);
    // Our shot was just sent: on our turn, with the board at rest, simulate it with the exact
    // engine and draw it from the next frame on, until the server's snapshots take over
    // (ShotPrediction). False when nothing is predicted (not our turn, pieces moving, another
    // turn, or a scene the engine refuses).
    bool predict(const proto::Shoot& shot, double local_s);
    // Forget the room (left it, or the seat is gone).
    void reset();

    const MatchView& view() const { return view_; }
    bool my_turn() const;
    bool spectator() const { return view_.you < 0; }
    // The side drawn at the bottom of the window: our own baseline's (seat 0's, the bottom one,
    // for a spectator). The view is turned by that side's quarter turns (screen_mapping.hpp).
    rules::Side view_side() const;
    // Seconds left on the shot clock by the server's clock, if one runs.
    std::optional<double> shot_clock_left_s(double local_s) const;
    // The seconds of our own shot clock's last kCountdownS, each once per turn (5, 4, ... 1) as
    // it is reached: the app plays a tick for it. Empty otherwise.
    std::optional<int> countdown_tick(double local_s);
    static constexpr double kCountdownS = 5.0;
    // The summary card of the board that just ended: shown kBoardSummaryS after its board_end,
    // unless dismissed or the game ended with it.
    bool board_summary_shown(double local_s) const;
    void dismiss_board_summary() { view_.board_summary.reset(); }
    static constexpr double kBoardSummaryS = 6.0;
    std::string seat_name(int seat) const;
    rules::Side seat_side(int seat) const { return client::seat_side(view_, seat); }

    // The board to draw at local_s; sound cues that became due are kept for take_sounds().
    std::vector<RenderedBody> render(double local_s);
    std::vector<SoundCue> take_sounds();
    // True while a shot is still being played on screen (the rendered time has not reached the
    // newest state, or the server says pieces move).
    bool animating() const;
    // The newest board (for placement checks), empty before the first state.
    std::vector<BodyState> board_now() const;
    // The coins on the board as last rendered, and what is left of them for one seat.
    const CoinsOnBoard& coins_on_board() const { return coins_; }
    std::optional<SeatCoins> coins_left(int seat) const;

    ServerClock& server_clock() { return server_clock_; }
    const ServerClock& server_clock() const { return server_clock_; }
    HudLog& log() { return log_; }
    // Every line said, the newest kTranscriptLines (the HUD shows only the last few for a few
    // seconds): what --final-state reports the player was told.
    const std::deque<HudLine>& transcript() const { return transcript_; }
    static constexpr std::size_t kTranscriptLines = 200;
    const HudLog& log() const { return log_; }
    // The seats' emotes on show and the player's mutes (kept across rooms).
    EmoteBoard& emotes() { return emotes_; }
    const EmoteBoard& emotes() const { return emotes_; }
    const PlayoutClock& playout() const { return playout_; }
    const InterpolationBuffer& buffer() const { return buffer_; }
    // Strokes predicted, bodies corrected by the server's snapshots, the largest difference.
    const PredictionStats& prediction_stats() const { return prediction_.stats(); }
    const ShotPrediction& prediction() const { return prediction_; }
    // The continuous time of the last render().
    double rendered_time_s() const { return last_render_s_; }
    // The shot a continuous time falls in (ShotTimeline::shot_time).
    using ShotTime = client::ShotTime;
    ShotTime shot_time(double continuous_s) const { return timeline_.shot_time(continuous_s); }

private:
    // The server's motion model (room_state "motion") for the buffer and the playout clock.
    void apply_motion(const proto::MotionInfo& motion);
    void on_room_state(const proto::RoomState& m, double local_s);
    void on_snapshot(const proto::Snapshot& m, double local_s);
    void on_event(const proto::Event& m, double local_s);
    void on_due(const proto::DueEvent& e, double local_s);
    // Posts a line for the HUD and keeps it in the transcript.
    void say(std::string text, Tone tone, double local_s);
    void on_forfeit_end(const proto::GameEndEvent& e, double local_s);
    void on_board_end(const proto::BoardEndEvent& e, double local_s);
    void on_shot_result(const proto::ShotResult& m, double local_s);
    void on_error(const proto::Error& m, double local_s);
    void cue(int turn, double t_s, SoundKind kind, double volume);
    BodyKind kind_of(int id) const;
    double continuous_now(double local_s) const;
    std::vector<RenderedBody> render_predicted(double t_s, double local_s);
    void drop_unconfirmed_prediction();

    PhysicsConfig physics_;
    PlayoutConfig playout_config_;
    InterpolationConfig interpolation_config_;
    MatchView view_;
    PlayoutClock playout_;
    InterpolationBuffer buffer_;
    ServerClock server_clock_;
    SoundCueSchedule sounds_;
    HudLog log_;
    EmoteBoard emotes_;
    std::map<int, BodyKind> kinds_;
    ShotTimeline timeline_;
    // The team and dues of the last `due` event since the last shot_result: the server sends one
    // per seat of the team, the HUD says it once.
    struct DueSaid {
        int team;
        int owed;
    };
    std::optional<DueSaid> due_said_;
    std::deque<HudLine> transcript_;
    // The seat whose forfeit (a leave, or a grace period that ran out) the last shot_result
    // reported: game_end's line names it. -1 when none.
    int forfeit_seat_ = -1;
    std::optional<std::pair<int, int>> last_tick_; // {turn, second} of the last countdown tick
    std::optional<std::int64_t> last_proto_seq_;
    std::uint64_t next_seq_ = 1;
    double last_render_s_ = 0.0;
    CoinsOnBoard coins_;
    ShotPrediction prediction_;
    int corrections_logged_ = 0;
};

} // namespace carrom::client
