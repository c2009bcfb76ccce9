#include "app_window.hpp"

#include "carrom/client/demo_link.hpp"
#include "carrom/client/game_over_text.hpp"
#include "carrom/client/settings_file.hpp"
#include "draw_util.hpp"
#include "network_link.hpp"
#include "unattended_modes.hpp"
#include "window_output.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <utility>

namespace carrom::client::app {
namespace {

// Demo screenshots and the benchmark step a fixed 1/60 s per frame (reproducible pictures); a
// networked client always follows real time, as the server does.
bool fixed_step(const AppOptions& o) {
    return o.demo && (!o.screenshot_path.empty() || o.bench_frames > 0);
}

std::string settings_file(const AppOptions& o) {
    if (!o.settings_path.empty()) {
        return o.settings_path;
    }
    return settings_path(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"));
}

} // namespace

AppWindow::AppWindow(const AppOptions& options, const sf::Font& font)
    : options_(options), font_(font), clock_(fixed_step(options)),
      geometry_(make_board_geometry(physics_)), model_(physics_), aim_(physics_),
      aim_assist_(physics_), board_painter_(geometry_), hud_(font), lobby_(font, options.name),
      menus_(settings_file(options), load_settings(settings_file(options))),
      records_(options.demo ? std::string() : options.url, options.ca_file),
      sound_(!options.mute && options.bench_frames == 0 && options.screenshot_path.empty()),
      session_(make_factory(), options.name,
               network_session_config(options.identity, options.demo ? "" : options.url)) {}

LinkFactory AppWindow::make_factory() {
    if (!options_.demo) {
        return make_network_link_factory(options_.ca_file);
    }
    DemoConfig demo;
    demo.first_shot_at_s = options_.demo_break_at_s;
    demo.autoplay_after_s = options_.demo_autoplay_s;
    const PhysicsConfig physics = physics_;
    return [this, demo, physics](const std::string&) -> std::unique_ptr<MessageLink> {
        return std::make_unique<DemoLink>(
            physics, [this] { return clock_.now(); }, demo);
    };
}

void AppWindow::handle_event(const sf::Event& e) {
    if (handle_window_event(window_, e, layout_, layout_seats_)) {
        return;
    }
    if (handle_menu_input(e)) {
        return;
    }
    if (session_.phase() == SessionPhase::Lobby) {
        handle_lobby_event(e);
        return;
    }
    if (model_.board_summary_shown(clock_.now()) && BoardSummaryPanel::dismisses(e)) {
        model_.dismiss_board_summary(); // the card between boards; the event still plays on
    }
    if (model_.view().in_room && handle_emote_key(e)) {
        return;
    }
    if (model_.view().in_room && model_.view().phase == proto::Phase::GameOver) {
        handle_game_over_input(e);
    } else if (model_.view().in_room) {
        handle_match_input(e);
    }
}

bool AppWindow::handle_menu_input(const sf::Event& e) {
    const MatchView& v = model_.view();
    const MatchMenus::Outcome out = menus_.on_event(e, v.in_room, v.rule_set);
    if (out.want_leave) {
        want_leave();
    } else if (out.leave) {
        back_to_lobby();
    }
    return out.used;
}

void AppWindow::want_leave() {
    const MatchView& v = model_.view();
    const bool running =
        v.you >= 0 && (v.phase == proto::Phase::Aiming || v.phase == proto::Phase::Moving ||
                       v.phase == proto::Phase::BoardOver);
    if (!running) {
        back_to_lobby();
        return;
    }
    aim_.cancel();
    menus_.ask_leave(v.seats.size() > 2 ? "Your team loses this game by forfeit."
                                        : "You lose this game: " + model_.seat_name(1 - v.you) +
                                              " wins it by forfeit.");
}

void AppWindow::handle_game_over_input(const sf::Event& e) {
    const auto choice = game_over_.on_event(e, game_over_words());
    if (choice == GameOverPanel::Choice::Rematch) {
        rematch_asked_ = session_.send_game(proto::Rematch{});
    } else if (choice == GameOverPanel::Choice::Lobby) {
        back_to_lobby();
    }
}

void AppWindow::back_to_lobby() {
    menus_.close();
    session_.leave_room();
    model_.reset();
    aim_.end_turn();
    aim_turn_ = -1;
    shot_sent_turn_ = -1;
    rematch_asked_ = false;
    announced_room_.clear();
    records_.room_left();
}

bool AppWindow::handle_emote_key(const sf::Event& e) {
    if (e.type != sf::Event::KeyPressed) {
        return false;
    }
    if (e.key.code == sf::Keyboard::E) {
        model_.emotes().set_all_muted(!model_.emotes().all_muted());
        model_.log().post(model_.emotes().all_muted() ? "Emotes muted (E shows them)"
                                                      : "Emotes shown (E mutes them)",
                          Tone::Info, clock_.now());
        return true;
    }
    const int index = static_cast<int>(e.key.code) - static_cast<int>(sf::Keyboard::Num1);
    const MatchView& v = model_.view();
    if (index < 0 || index >= static_cast<int>(proto::kEmoteNames.size()) || v.you < 0 ||
        v.phase == proto::Phase::Waiting) {
        return false;
    }
    session_.send_game(
        proto::EmoteMessage{proto::kEmoteNames[static_cast<std::size_t>(index)].value});
    return true;
}

void AppWindow::handle_match_input(const sf::Event& e) {
    const std::vector<BodyState> pieces = model_.board_now();
    const ScreenMapping m = mapping();
    auto board_at = [&m](int x, int y) {
        return m.to_board({static_cast<double>(x), static_cast<double>(y)});
    };
    std::optional<ShotIntent> shot;
    switch (e.type) {
    case sf::Event::MouseButtonPressed:
        if (e.mouseButton.button == sf::Mouse::Left) {
            aim_.pointer_down(board_at(e.mouseButton.x, e.mouseButton.y), pieces);
        }
        break;
    case sf::Event::MouseMoved:
        aim_.pointer_move(board_at(e.mouseMove.x, e.mouseMove.y), pieces);
        break;
    case sf::Event::MouseButtonReleased:
        if (e.mouseButton.button == sf::Mouse::Left) {
            shot = aim_.pointer_up(board_at(e.mouseButton.x, e.mouseButton.y), pieces);
        }
        break;
    case sf::Event::KeyPressed:
        if (e.key.code == sf::Keyboard::Escape) {
            aim_.cancel();
        } else if (e.key.code == sf::Keyboard::Left || e.key.code == sf::Keyboard::Right) {
            // Screen right as a direction along our baseline (the view may be turned).
            const double along = along_baseline(aim_.side(), m.direction_to_board({1.0, 0.0}));
            const int dir = (e.key.code == sf::Keyboard::Left ? -1 : 1) * (along < 0.0 ? -1 : 1);
            aim_.nudge(dir, e.key.shift, pieces);
        }
        break;
    default:
        break;
    }
    if (aim_.take_moved()) {
        aim_dirty_ = true;
    }
    if (shot) {
        const int turn = model_.view().turn;
        const proto::Shoot shoot{turn, shot->x_px, shot->angle_rad, shot->power};
        if (session_.send_game(shoot)) {
            shot_sent_turn_ = turn;
            aim_.end_turn();
            const bool predicted = model_.predict(shoot, clock_.now()); // drawn from next frame
            frame_log_.shoot(shoot, predicted);
        }
    }
}

void AppWindow::sync_aim(double now) {
    const MatchView& v = model_.view();
    const bool can_aim = model_.my_turn() && !model_.animating() && shot_sent_turn_ != v.turn;
    if (!can_aim) {
        aim_.end_turn();
        return;
    }
    if (aim_.phase() == AimPhase::Inactive) {
        const double x = aim_turn_ == v.turn ? aim_.striker_x() : physics_.centre().x;
        aim_.begin_turn(model_.seat_side(v.you), x);
        aim_turn_ = v.turn;
        aim_dirty_ = true;
    }
    // Tell the room where the striker is, at most 20 times a second.
    if (aim_dirty_ && now - last_aim_sent_s_ >= 0.05) {
        session_.send_game(proto::Aim{v.turn, aim_.striker_x()});
        last_aim_sent_s_ = now;
        aim_dirty_ = false;
    }
}

void AppWindow::update(double now) {
    for (const proto::ServerMessage& m : session_.update(now)) {
        if (std::holds_alternative<proto::Error>(m) || std::holds_alternative<proto::Welcome>(m)) {
            shot_sent_turn_ = -1; // a rejected shot, or one lost with the link: aim again if due
        }
        if (std::holds_alternative<proto::ShotResult>(m)) {
            ++shots_seen_;
        }
        if (const auto* room = std::get_if<proto::RoomState>(&m)) {
            room_ = *room;
        }
        model_.handle(m, now);
    }
    if (session_.seat_lost() && model_.view().in_room) {
        back_to_lobby(); // the server no longer holds our seat: the lobby says so
    }
    for (const ClientSession::PongSample& p : session_.take_pongs()) {
        model_.server_clock().round_trip(p.server_ms, p.sent_s, p.received_s);
    }
    if (model_.view().phase != proto::Phase::GameOver) {
        rematch_asked_ = false; // a new game started (or none is over)
    }
    // Doubles has a seat bar below the board.
    const int seats = model_.view().in_room ? static_cast<int>(model_.view().seats.size()) : 2;
    if (seats != layout_seats_) {
        layout_seats_ = seats;
        const sf::Vector2u size = window_.getSize();
        layout_ = make_layout(size.x, size.y, layout_seats_, true);
    }
    // Render first: the aim starts in the very frame the board comes to rest.
    bodies_ = model_.render(now);
    if (menus_.settings().reduced_motion) {
        // Reduced motion: a pocketed piece vanishes at once instead of dropping into the pocket.
        std::erase_if(bodies_, [](const RenderedBody& b) { return b.falling; });
    }
    sync_aim(now);
    announce_room();
    update_records(now);
    const Settings& settings = menus_.settings();
    if (model_.countdown_tick(now)) {
        // the shot clock's last seconds
        sound_.play(SoundCue{0.0, SoundKind::Click, 0.7}, settings.volume / 100.0, settings.muted);
    }
    for (const SoundCue& cue : model_.take_sounds()) {
        sound_.play(cue, settings.volume / 100.0, settings.muted);
    }
}

int AppWindow::run() {
    sf::ContextSettings settings;
    settings.antialiasingLevel = options_.msaa;
    window_.create(sf::VideoMode(options_.width, options_.height),
                   "Carrom" + std::string(options_.demo ? " (demo)" : ""), sf::Style::Default,
                   settings);
    if (!window_.isOpen()) {
        std::cerr << "carrom-client: could not open a window (is DISPLAY set?)\n";
        return 1;
    }
    if (!options_.frame_log_path.empty()) {
        if (auto problem = frame_log_.open(options_.frame_log_path)) {
            std::cerr << "carrom-client: " << *problem << "\n";
            return 2;
        }
    }
    if (!fixed_step(options_)) {
        window_.setVerticalSyncEnabled(true);
        // A screenshot of a networked match counts frames at 60 per second of real time.
        window_.setFramerateLimit(options_.screenshot_path.empty() ? 144 : 60);
    }
    unattended_ = make_unattended_mode(options_);
    const sf::Vector2u size = window_.getSize();
    window_.setView(sf::View(sf::FloatRect(0.0f, 0.0f, f(size.x), f(size.y))));
    layout_ = make_layout(size.x, size.y, layout_seats_, true);
    if (options_.request) {
        session_.request(*options_.request);
    }
    session_.start(clock_.now());
    int frame = 0;
    while (window_.isOpen()) {
        const auto t0 = std::chrono::steady_clock::now();
        const std::clock_t cpu0 = std::clock();
        sf::Event event;
        while (window_.pollEvent(event)) {
            handle_event(event);
        }
        const double now = clock_.now();
        update(now);
        if (replay_exit_) {
            window_.close();
            return *replay_exit_;
        }
        for (const sf::Event& e : std::exchange(unattended_input_, {})) {
            handle_event(e);
        }
        draw(now);
        if (model_.view().in_room) {
            frame_log_.frame(frame, model_, bodies_, session_.phase());
        }
        ++frame;
        if (const std::optional<int> code = unattended_frame(frame)) {
            window_.close();
            return *code;
        }
        window_.display();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        const double cpu_ms = 1000.0 * static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
        shown_ = FrameTime{ms, cpu_ms, model_.animating()};
        clock_.tick();
    }
    return 0;
}

std::optional<int> AppWindow::unattended_frame(int frame) {
    if (!unattended_) {
        return std::nullopt;
    }
    const ScreenMapping m = mapping();
    const MatchView& v = model_.view();
    const LiveTurn live{room_, aim_, shot_sent_turn_ == v.turn};
    UnattendedFrame f{
        frame,
        window_,
        model_,
        &live,
        v.in_room && v.phase == proto::Phase::GameOver && v.result && !model_.animating(),
        [this] {
            return session_.status_text() + ", " + std::to_string(shots_seen_) + " shots seen";
        },
        shots_seen_,
        m,
        physics_,
        bodies_,
        aim_striker_drawn_,
        hud_.overlay_area(),
        shown_,
        board_painter_.repaints(),
        hud_.bar_repaints(),
        unattended_input_,
        model_.board_summary_shown(clock_.now()),
        ui_json()};
    unattended_->on_frame(f);
    return unattended_->done();
}

std::string AppWindow::ui_json() const {
    const auto rect = [](const Rect& r) {
        return nlohmann::json{{"x", r.x}, {"y", r.y}, {"w", r.w}, {"h", r.h}};
    };
    nlohmann::json messages = nlohmann::json::array();
    for (const auto& [text, r] : hud_.message_rects()) {
        nlohmann::json m = rect(r);
        m["text"] = text;
        messages.push_back(m);
    }
    const auto rects = [&rect](const std::vector<Rect>& list) {
        nlohmann::json out = nlohmann::json::array();
        for (const Rect& r : list) {
            out.push_back(rect(r));
        }
        return out;
    };
    const Settings& s = menus_.settings();
    return nlohmann::json{
        {"open", menus_.open_name()},
        {"tip", menus_.tip_step()},
        {"rules_tab", menus_.rules_tab()},
        {"leave_text", menus_.open() == MatchMenus::Open::Leave ? menus_.leave_consequence() : ""},
        {"settings",
         {{"volume", s.volume},
          {"muted", s.muted},
          {"reduced_motion", s.reduced_motion},
          {"coached", s.coached}}},
        {"side", rect(layout_.side)},
        {"messages", messages},
        {"bar_buttons", rects(menus_.bar_buttons())},
        {"dialog_buttons", rects(menus_.dialog_buttons())},
        {"tips_buttons", rects(menus_.tips_buttons())},
        {"lobby", !model_.view().in_room},
        {"lobby_buttons", rects(lobby_page_ == LobbyPage::Main ? lobby_.control_rects(lobby_area())
                                                               : std::vector<Rect>{})},
        {"leaderboard_buttons",
         rects(lobby_page_ == LobbyPage::Leaderboard ? leaderboard_view_.control_rects(lobby_area())
                                                     : std::vector<Rect>{})},
        {"matches_buttons", rects(lobby_page_ == LobbyPage::Matches
                                      ? match_list_.control_rects(lobby_area(), records_.matches())
                                      : std::vector<Rect>{})},
        {"lobby_choice",
         {{"name", lobby_.name()},
          {"rule_set", std::string(proto::to_string(lobby_.rule_set()))},
          {"bot_level", std::string(proto::to_string(lobby_.bot_level()))}}},
        {"rule_set", std::string(proto::to_string(model_.view().rule_set))},
        {"aim_assist", model_.view().aim_assist},
        {"session", session_.phase() == SessionPhase::Lobby ? "lobby" : "other"},
        {"records", records_json()}}
        .dump();
}

// "room CODE" on stdout once per room, for scripts that start a second player (or a bot) with
// that code.
void AppWindow::announce_room() {
    const MatchView& v = model_.view();
    if (!v.in_room || v.code.empty() || v.code == announced_room_) {
        return;
    }
    announced_room_ = v.code;
    std::cout << "room " << v.code << std::endl;
}

} // namespace carrom::client::app
