#pragma once
// The desktop client's window: lobby, match view, input, sound, and at most one unattended mode
// (unattended_mode.hpp: screenshot and report, final state, timeout, frame benchmark, autoplay)
// that sees every frame. One class over three files: app_window.cpp (the loop, messages, input),
// app_window_draw.cpp (drawing), app_window_lobby.cpp (the lobby's pages and the ratings read
// from the server's HTTP API).

#include "app.hpp"
#include "blitter.hpp"
#include "board_painter.hpp"
#include "board_summary_panel.hpp"
#include "carrom/client/aim_assist.hpp"
#include "carrom/client/aim_controller.hpp"
#include "carrom/client/board_geometry.hpp"
#include "carrom/client/client_session.hpp"
#include "carrom/client/connection.hpp"
#include "carrom/client/game_over_text.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "frame_clock.hpp"
#include "frame_log.hpp"
#include "game_over_panel.hpp"
#include "hud_painter.hpp"
#include "leaderboard_view.hpp"
#include "lobby_view.hpp"
#include "match_list_view.hpp"
#include "match_menus.hpp"
#include "reconnect_panel.hpp"
#include "server_records.hpp"
#include "sound_player.hpp"
#include "unattended_mode.hpp"

#include <SFML/Graphics.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace carrom::client::app {

class AppWindow {
public:
    AppWindow(const AppOptions& options, const sf::Font& font);

    int run();

private:
    LinkFactory make_factory();
    void handle_event(const sf::Event& e);
    void handle_match_input(const sf::Event& e);
    void handle_game_over_input(const sf::Event& e);
    // The menus' share of an event (match_menus.hpp); true when it was theirs.
    bool handle_menu_input(const sf::Event& e);
    // Leave pressed: asks first while our game runs (leaving forfeits it), else leaves.
    void want_leave();
    // What the menus and the side area show, as JSON for the screenshot report.
    std::string ui_json() const;
    void back_to_lobby();
    void update(double now);
    void sync_aim(double now);
    void draw(double now);
    void draw_aim();
    // The first-contact guide of the pull in progress (rooms with aim assist).
    void draw_aim_assist(sf::VertexArray& tris, const ScreenMapping& m);
    // Each seat's emote on show, beside its side of the board.
    void draw_emotes(double now);
    // Keys 1-8 send an emote (a seated player in a started game); E mutes or shows them all.
    bool handle_emote_key(const sf::Event& e);
    void draw_status_panel(const std::string& title, const std::string& detail);
    // The lobby's share of an event: its main page, the leaderboard or My matches.
    void handle_lobby_event(const sf::Event& e);
    void draw_lobby(const std::string& error, bool can_choose);
    // Reads the server's records in the background and hands the HUD the seats' ratings; opens a
    // match's journal that came as a replay.
    void update_records(double now);
    // Runs the replay window (the lobby's window hidden meanwhile); back in the lobby after,
    // unless an unattended mode ended the replay (replay_exit_).
    void open_replay(ReplayModel replay);
    // Each seat's rating text (RatingBook::seat_text; "" for a bot or an empty seat).
    std::vector<std::string> seat_rating_texts() const;
    // The game-over panel's words with the seats' ratings after a rated game.
    GameOverText game_over_words() const;
    // The lobby's pages and the ratings, for the screenshot report.
    nlohmann::json records_json() const;
    void announce_room();
    // Hands the frame just drawn (number `frame`) to the unattended mode; its exit code when it
    // ends the run.
    std::optional<int> unattended_frame(int frame);
    // Where the lobby is drawn: the board's square without a side area.
    Rect lobby_area() const { return make_layout(window_.getSize().x, window_.getSize().y).board; }
    ScreenMapping mapping() const {
        return make_mapping(layout_.board, physics_.board_size_px, model_.view_side());
    }

    AppOptions options_;
    const sf::Font& font_;
    FrameClock clock_;
    PhysicsConfig physics_{};
    BoardGeometry geometry_;
    MatchModel model_;
    AimController aim_;
    AimAssist aim_assist_;
    Blitter blitter_;
    BoardPainter board_painter_;
    HudPainter hud_;
    LobbyView lobby_;
    MatchMenus menus_;
    GameOverPanel game_over_;
    BoardSummaryPanel board_summary_;
    ReconnectPanel reconnect_panel_;
    ServerRecords records_;
    enum class LobbyPage { Main, Leaderboard, Matches };
    LobbyPage lobby_page_ = LobbyPage::Main;
    LeaderboardView leaderboard_view_;
    MatchListView match_list_;
    bool journal_asked_ = false;     // My matches asked for a replay's journal
    std::optional<int> replay_exit_; // an unattended replay's exit code: it ends the run
    bool in_lobby_ = false;          // the session was in the lobby last frame
    SoundPlayer sound_;
    ClientSession session_;
    sf::RenderWindow window_;
    ScreenLayout layout_;
    int layout_seats_ = 2; // the seat count layout_ was made for
    std::vector<RenderedBody> bodies_;
    int aim_turn_ = -1;       // the turn the aim controller was set up for
    int shot_sent_turn_ = -1; // the turn we already shot in (no double shots)
    double last_aim_sent_s_ = -1.0;
    bool aim_dirty_ = false;
    int shots_seen_ = 0;                    // shot results received
    std::optional<Vec2> aim_striker_drawn_; // a striker being placed, drawn this frame
    std::string announced_room_;            // the room code last printed on stdout
    bool rematch_asked_ = false;            // sent `rematch` for the game that is over
    std::optional<proto::RoomState> room_;  // the newest room state (what --autoplay plays from)
    FrameLog frame_log_;                    // --frame-log
    std::unique_ptr<UnattendedMode> unattended_; // null: none
    std::vector<sf::Event> unattended_input_;    // the mode's events for the next frame
    std::optional<FrameTime> shown_;             // the last frame displayed
};

} // namespace carrom::client::app
