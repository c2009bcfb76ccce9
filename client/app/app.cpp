#include "app.hpp"

#include "auto_player.hpp"
#include "board_painter.hpp"
#include "carrom/client/aim_controller.hpp"
#include "carrom/client/board_report.hpp"
#include "carrom/client/demo_link.hpp"
#include "carrom/client/game_over_text.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "draw_util.hpp"
#include "font.hpp"
#include "frame_log.hpp"
#include "game_over_panel.hpp"
#include "hud_painter.hpp"
#include "lobby_view.hpp"
#include "network_link.hpp"
#include "reconnect_panel.hpp"
#include "sound_player.hpp"
#include "text.hpp"

#include <SFML/Graphics.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <vector>

namespace carrom::client::app {
namespace {

// Real time, or a fixed 1/60 s per frame for screenshots and the benchmark (reproducible).
class FrameClock {
public:
    explicit FrameClock(bool fixed_step) : fixed_(fixed_step) {}
    double now() const {
        if (fixed_) {
            return static_cast<double>(frame_) / 60.0;
        }
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    void tick() { ++frame_; }

private:
    bool fixed_;
    long frame_ = 0;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

double percentile(std::vector<double> v, double p) {
    if (v.empty()) {
        return 0.0;
    }
    std::sort(v.begin(), v.end());
    const auto i = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1;
    return v[std::min(i, v.size() - 1)];
}

struct FrameStats {
    std::vector<double> all_ms;
    std::vector<double> moving_ms;
    std::vector<double> cpu_ms; // CPU time of the whole process (renderer threads included)
};

struct LayerCounts {
    long board = 0; // board band and piece atlas paints
    long hud = 0;   // HUD bar paints
};

void print_bench(const FrameStats& s, unsigned w, unsigned h, unsigned msaa,
                 const LayerCounts& paints) {
    std::printf("{\"width\": %u, \"height\": %u, \"msaa\": %u, \"frames\": %zu, "
                "\"p50_ms\": %.3f, \"p99_ms\": %.3f, \"max_ms\": %.3f, \"moving_frames\": %zu, "
                "\"moving_p50_ms\": %.3f, \"moving_p99_ms\": %.3f, \"cpu_p50_ms\": %.3f, "
                "\"cpu_p99_ms\": %.3f, \"board_paints\": %ld, \"hud_paints\": %ld}\n",
                w, h, msaa, s.all_ms.size(), percentile(s.all_ms, 0.5), percentile(s.all_ms, 0.99),
                percentile(s.all_ms, 1.0), s.moving_ms.size(), percentile(s.moving_ms, 0.5),
                percentile(s.moving_ms, 0.99), percentile(s.cpu_ms, 0.5),
                percentile(s.cpu_ms, 0.99), paints.board, paints.hud);
}

// Demo screenshots and the benchmark step a fixed 1/60 s per frame (reproducible pictures); a
// networked client always follows real time, as the server does.
bool fixed_step(const AppOptions& o) {
    return o.demo && (!o.screenshot_path.empty() || o.bench_frames > 0);
}

class App {
public:
    App(const AppOptions& options, const sf::Font& font)
        : options_(options), font_(font), clock_(fixed_step(options)),
          geometry_(make_board_geometry(physics_)), model_(physics_), aim_(physics_),
          board_painter_(geometry_), hud_(font), lobby_(font),
          sound_(!options.mute && options.bench_frames == 0 && options.screenshot_path.empty()),
          session_(make_factory(), options.name, network_session_config()) {
        if (options.autoplay) {
            auto_player_.emplace(*options.autoplay, 1);
        }
    }

    int run();

private:
    LinkFactory make_factory() {
        if (!options_.demo) {
            return make_network_link_factory(options_.url);
        }
        DemoConfig demo;
        demo.first_shot_at_s = options_.demo_break_at_s;
        demo.autoplay_after_s = options_.demo_autoplay_s;
        const PhysicsConfig physics = physics_;
        return [this, demo, physics]() -> std::unique_ptr<MessageLink> {
            return std::make_unique<DemoLink>(
                physics, [this] { return clock_.now(); }, demo);
        };
    }
    void handle_event(const sf::Event& e);
    void handle_match_input(const sf::Event& e);
    void handle_game_over_input(const sf::Event& e);
    void back_to_lobby();
    void update(double now);
    void sync_aim(double now);
    void draw(double now);
    void draw_aim();
    void draw_status_panel(const std::string& title, const std::string& detail);
    bool save_screenshot();
    bool timed_out(std::chrono::steady_clock::time_point started) const;
    bool bench_done(int frame, double ms, double cpu_ms);
    bool screenshot_due(int frame) const;
    int finish_screenshot();
    void announce_room();
    void autoplay();
    bool final_state_due() const;
    int write_final_state();
    ScreenMapping mapping() const {
        return make_mapping(layout_.board, physics_.board_size_px, model_.flipped());
    }

    AppOptions options_;
    const sf::Font& font_;
    FrameClock clock_;
    PhysicsConfig physics_{};
    BoardGeometry geometry_;
    MatchModel model_;
    AimController aim_;
    Blitter blitter_;
    BoardPainter board_painter_;
    HudPainter hud_;
    LobbyView lobby_;
    GameOverPanel game_over_;
    ReconnectPanel reconnect_panel_;
    SoundPlayer sound_;
    ClientSession session_;
    sf::RenderWindow window_;
    ScreenLayout layout_;
    std::vector<RenderedBody> bodies_;
    int aim_turn_ = -1;       // the turn the aim controller was set up for
    int shot_sent_turn_ = -1; // the turn we already shot in (no double shots)
    double last_aim_sent_s_ = -1.0;
    bool aim_dirty_ = false;
    FrameStats bench_;                      // --bench-frames
    int shots_seen_ = 0;                    // shot results received
    std::optional<Vec2> aim_striker_drawn_; // a striker being placed, drawn this frame
    std::string announced_room_;            // the room code last printed on stdout
    bool rematch_asked_ = false;            // sent `rematch` for the game that is over
    std::optional<AutoPlayer> auto_player_; // --autoplay
    std::optional<proto::RoomState> room_;  // the newest room state (what --autoplay plays from)
    int auto_turn_ = -1;                    // the turn --autoplay last aimed in
    FrameLog frame_log_;                    // --frame-log
};

void App::handle_event(const sf::Event& e) {
    if (e.type == sf::Event::Closed) {
        window_.close();
        return;
    }
    if (e.type == sf::Event::Resized) {
        const float w = static_cast<float>(e.size.width);
        const float h = static_cast<float>(e.size.height);
        window_.setView(sf::View(sf::FloatRect(0.0f, 0.0f, w, h)));
        layout_ = make_layout(w, h);
        return;
    }
    if (session_.phase() == SessionPhase::Lobby) {
        if (auto request = lobby_.on_event(e, layout_.board)) {
            session_.request(*request);
        }
        return;
    }
    if (model_.view().in_room && model_.view().phase == proto::Phase::GameOver) {
        handle_game_over_input(e);
    } else if (model_.view().in_room) {
        handle_match_input(e);
    }
}

void App::handle_game_over_input(const sf::Event& e) {
    const auto choice = game_over_.on_event(e, game_over_text(model_.view(), rematch_asked_));
    if (choice == GameOverPanel::Choice::Rematch) {
        rematch_asked_ = session_.send_game(proto::Rematch{});
    } else if (choice == GameOverPanel::Choice::Lobby) {
        back_to_lobby();
    }
}

void App::back_to_lobby() {
    session_.leave_room();
    model_.reset();
    aim_.end_turn();
    aim_turn_ = -1;
    shot_sent_turn_ = -1;
    rematch_asked_ = false;
    announced_room_.clear();
}

void App::handle_match_input(const sf::Event& e) {
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
            // Screen left is board -x, or +x when the view is turned.
            int dir = e.key.code == sf::Keyboard::Left ? -1 : 1;
            dir = model_.flipped() ? -dir : dir;
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

void App::sync_aim(double now) {
    const MatchView& v = model_.view();
    const bool can_aim = model_.my_turn() && !model_.animating() && shot_sent_turn_ != v.turn;
    if (!can_aim) {
        aim_.end_turn();
        return;
    }
    if (aim_.phase() == AimPhase::Inactive) {
        const double x = aim_turn_ == v.turn ? aim_.striker_x() : physics_.centre().x;
        aim_.begin_turn(model_.seat_baseline(v.you), x);
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

void App::update(double now) {
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
    // Render first: the aim starts in the very frame the board comes to rest.
    bodies_ = model_.render(now);
    sync_aim(now);
    announce_room();
    for (const SoundCue& cue : model_.take_sounds()) {
        sound_.play(cue);
    }
}

void App::draw_aim() {
    aim_striker_drawn_.reset();
    const ScreenMapping m = mapping();
    const MatchView& v = model_.view();
    if (aim_.phase() != AimPhase::Inactive) {
        const Vec2 s = aim_.striker_px();
        if (aim_.phase() == AimPhase::Pulling) {
            const ShotIntent shot = aim_.pending_shot();
            const double frac = aim_.power_fraction();
            sf::VertexArray tris(sf::Triangles);
            const Vec2 dir{std::cos(shot.angle_rad), std::sin(shot.angle_rad)};
            const double reach = 40.0 + 260.0 * frac;
            for (double d = physics_.striker_radius_px + 4.0; d < reach; d += 14.0) {
                add_line(tris, m.to_screen(s + dir * d),
                         m.to_screen(s + dir * std::min(d + 8.0, reach)),
                         std::max(m.length_to_screen(2.0), 1.5), sf::Color(255, 255, 255, 210));
            }
            add_line(tris, m.to_screen(s), m.to_screen(s - dir * (20.0 + 140.0 * frac)),
                     std::max(m.length_to_screen(1.0), 1.0), sf::Color(40, 20, 10, 150));
            const auto red = static_cast<sf::Uint8>(std::lround(60 + 195 * frac));
            const auto green = static_cast<sf::Uint8>(std::lround(210 - 150 * frac));
            add_arc(tris, m.to_screen(s), m.length_to_screen(physics_.striker_radius_px + 7.0),
                    m.length_to_screen(4.0), -std::numbers::pi / 2.0,
                    -std::numbers::pi / 2.0 + 2.0 * std::numbers::pi * frac,
                    sf::Color(red, green, 40), 48);
            window_.draw(tris);
            const Vec2 label = m.to_screen(s + Vec2{0.0, 0.0}) +
                               Vec2{0.0, -m.length_to_screen(physics_.striker_radius_px + 22.0)};
            hud_.texts().draw(window_, "Power " + std::to_string(std::lround(100.0 * frac)) + "%",
                              static_cast<unsigned>(std::max(12.0, m.length_to_screen(11.0))),
                              f(label.x), f(label.y), sf::Color::White, Align::Centre);
        }
        board_painter_.draw_striker(window_, blitter_, m, s, 1.0, !aim_.placement().legal);
        aim_striker_drawn_ = s;
        if (!aim_.placement().legal) {
            const Vec2 label =
                m.to_screen(s) + Vec2{0.0, m.length_to_screen(physics_.striker_radius_px + 16.0)};
            hud_.texts().draw(window_, "Overlaps a piece",
                              static_cast<unsigned>(std::max(12.0, m.length_to_screen(10.0))),
                              f(label.x), f(label.y), sf::Color(255, 90, 80), Align::Centre);
        }
        return;
    }
    if (v.phase == proto::Phase::Aiming && !model_.animating() && v.to_play != v.you) {
        // The opponent's striker, where they are placing it.
        const double x = v.aim_x_px.value_or(physics_.centre().x);
        const Vec2 s{clamp_baseline_x(physics_, x),
                     baseline_y(physics_, model_.seat_baseline(v.to_play))};
        board_painter_.draw_striker(window_, blitter_, m, s, 0.85, false);
        aim_striker_drawn_ = s;
    }
}

void App::draw_status_panel(const std::string& title, const std::string& detail) {
    const Rect& b = layout_.board;
    draw_panel(window_, b, sf::Color(20, 12, 8, 200));
    const float cx = f(b.x + b.w / 2.0);
    draw_text(window_, font_, title, static_cast<unsigned>(std::clamp(b.h * 0.05, 18.0, 44.0)), cx,
              f(b.y + b.h * 0.42), sf::Color(236, 184, 64), Align::Centre);
    // One sentence per line, so long reasons stay inside the window.
    const auto size = static_cast<unsigned>(std::clamp(b.h * 0.024, 12.0, 22.0));
    std::size_t start = 0;
    double y = b.y + b.h * 0.52;
    while (start < detail.size()) {
        std::size_t end = detail.find(". ", start);
        end = end == std::string::npos ? detail.size() : end + 1;
        draw_text(window_, font_, detail.substr(start, end - start), size, cx, f(y),
                  sf::Color(242, 232, 214), Align::Centre);
        y += size * 1.5;
        start = end < detail.size() ? end + 1 : end;
    }
}

void App::draw(double now) {
    const ScreenMapping m = mapping();
    const SessionPhase phase = session_.phase();
    const Rect band{0.0, layout_.top_bar.h, layout_.top_bar.w,
                    layout_.bottom_bar.y - layout_.top_bar.h};
    if (model_.view().in_room) {
        // The bars and the band between them cover the window: no clear.
        board_painter_.draw_board(window_, blitter_, m, band);
        board_painter_.draw_pieces(window_, blitter_, m, bodies_);
        draw_aim();
        // While the link is lost the card over the board has the details; the bar its title.
        const bool linked = phase == SessionPhase::InRoom || phase == SessionPhase::Joining;
        const ReconnectText card =
            reconnect_text(phase, session_.reconnect_info(now), session_.status_text());
        ConnectionLine line{linked ? session_.status_text() : card.title, linked,
                            session_.rtt_ms()};
        hud_.draw(window_, blitter_, layout_, model_, line, now);
        if (model_.view().phase == proto::Phase::GameOver) {
            game_over_.draw(window_, blitter_, hud_.texts(), layout_.board,
                            game_over_text(model_.view(), rematch_asked_));
        }
        if (phase == SessionPhase::Reconnecting || phase == SessionPhase::Failed ||
            phase == SessionPhase::Connecting || phase == SessionPhase::Greeting) {
            reconnect_panel_.draw(window_, hud_.texts(), layout_.board, card);
        }
        return;
    }
    window_.clear(BoardPainter::kMargin);
    board_painter_.draw_board(window_, blitter_, m, band);
    std::string error;
    for (const HudLine& l : model_.log().visible(now)) {
        if (l.tone == Tone::Error) {
            error = l.text;
        }
    }
    switch (phase) {
    case SessionPhase::Lobby:
        lobby_.draw(window_, layout_.board, options_.name, session_.status_text(), error, true);
        break;
    case SessionPhase::Joining:
        lobby_.draw(window_, layout_.board, options_.name, session_.status_text(), error, false);
        break;
    case SessionPhase::Failed:
        draw_status_panel("Cannot connect", session_.status_text());
        break;
    default:
        draw_status_panel(options_.demo ? "Starting the demo" : "Connecting to " + options_.url,
                          session_.status_text());
        break;
    }
}

// --autoplay: one queued mouse event per frame; on our turn, at rest, with the striker idle and
// the room state of this turn, the strategy aims (again, differently, when the last gesture of
// this turn made no shot or the server refused it).
void App::autoplay() {
    if (!auto_player_) {
        return;
    }
    if (auto event = auto_player_->next_event()) {
        handle_event(*event);
        return;
    }
    const MatchView& v = model_.view();
    if (aim_.phase() != AimPhase::Idle || !room_ || room_->turn != v.turn ||
        room_->phase != proto::Phase::Aiming || shot_sent_turn_ == v.turn) {
        return;
    }
    if (auto_turn_ == v.turn) {
        auto_player_->refused();
    }
    auto_turn_ = v.turn;
    auto_player_->aim(*room_, aim_.striker_x(), aim_.baseline(), mapping(), physics_);
}

bool App::final_state_due() const {
    return !options_.final_state_path.empty() && model_.view().in_room &&
           model_.view().phase == proto::Phase::GameOver && model_.view().result &&
           !model_.animating();
}

int App::write_final_state() {
    std::ofstream out(options_.final_state_path);
    out << final_state_json(model_.view(), model_.board_now()) << "\n";
    if (!out) {
        std::cerr << "carrom-client: could not write " << options_.final_state_path << "\n";
        return 1;
    }
    std::cout << "final state " << options_.final_state_path << std::endl;
    return 0;
}

// "room CODE" on stdout once per room, for scripts that start a second player (or a bot) with
// that code.
void App::announce_room() {
    const MatchView& v = model_.view();
    if (!v.in_room || v.code.empty() || v.code == announced_room_) {
        return;
    }
    announced_room_ = v.code;
    std::cout << "room " << v.code << std::endl;
}

bool App::screenshot_due(int frame) const {
    if (options_.screenshot_path.empty() || frame < options_.frames) {
        return false;
    }
    return options_.after_shots <= 0 ||
           (shots_seen_ >= options_.after_shots && !model_.animating());
}

int App::finish_screenshot() {
    const bool saved = save_screenshot();
    if (!saved) {
        std::cerr << "carrom-client: could not save " << options_.screenshot_path << "\n";
        return 1;
    }
    if (!options_.report_path.empty()) {
        const sf::Vector2u size = window_.getSize();
        std::ofstream out(options_.report_path);
        std::vector<RenderedBody> drawn = bodies_;
        if (aim_striker_drawn_) {
            drawn.push_back(
                RenderedBody{-1, BodyKind::Striker, *aim_striker_drawn_, 1.0, 1.0, false});
        }
        const ReportContext context{static_cast<double>(size.x), static_cast<double>(size.y),
                                    shots_seen_, hud_.overlay_area()};
        out << board_report_json(model_.view(), drawn, mapping(), context) << "\n";
        if (!out) {
            std::cerr << "carrom-client: could not write " << options_.report_path << "\n";
            return 1;
        }
    }
    std::cout << "saved " << options_.screenshot_path << std::endl;
    return 0;
}

bool App::save_screenshot() {
    sf::Texture shot;
    const sf::Vector2u size = window_.getSize();
    if (!shot.create(size.x, size.y)) {
        return false;
    }
    shot.update(window_);
    return shot.copyToImage().saveToFile(options_.screenshot_path);
}

bool App::timed_out(std::chrono::steady_clock::time_point started) const {
    if (options_.timeout_s <= 0.0 ||
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() <=
            options_.timeout_s) {
        return false;
    }
    std::cerr << "carrom-client: gave up after " << options_.timeout_s << " s ("
              << session_.status_text() << ", " << shots_seen_ << " shots seen)\n";
    return true;
}

// Records one frame's times for --bench-frames (after the warm-up); prints the statistics and
// returns true after the last one.
bool App::bench_done(int frame, double ms, double cpu_ms) {
    constexpr int kWarmupFrames = 10;
    if (options_.bench_frames <= 0 || frame <= kWarmupFrames) {
        return false;
    }
    bench_.all_ms.push_back(ms);
    bench_.cpu_ms.push_back(cpu_ms);
    if (model_.animating()) {
        bench_.moving_ms.push_back(ms);
    }
    if (frame < options_.bench_frames + kWarmupFrames) {
        return false;
    }
    const sf::Vector2u size = window_.getSize();
    print_bench(bench_, size.x, size.y, options_.msaa,
                {board_painter_.repaints(), hud_.bar_repaints()});
    return true;
}

int App::run() {
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
    const auto started = std::chrono::steady_clock::now();
    const sf::Vector2u size = window_.getSize();
    window_.setView(sf::View(sf::FloatRect(0.0f, 0.0f, f(size.x), f(size.y))));
    layout_ = make_layout(size.x, size.y);
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
        autoplay();
        draw(now);
        if (model_.view().in_room) {
            frame_log_.frame(frame, model_, bodies_, session_.phase());
        }
        ++frame;
        if (final_state_due()) {
            const int code = write_final_state();
            window_.close();
            return code;
        }
        if (screenshot_due(frame)) {
            const int code = finish_screenshot();
            window_.close();
            return code;
        }
        if (timed_out(started)) {
            window_.close();
            return 3;
        }
        window_.display();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        const double cpu_ms = 1000.0 * static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
        if (bench_done(frame, ms, cpu_ms)) {
            window_.close();
            return 0;
        }
        clock_.tick();
    }
    return 0;
}

} // namespace

int run_app(const AppOptions& options) {
    sf::Font font;
    std::string error;
    if (!load_font(font, error)) {
        std::cerr << "carrom-client: " << error << "\n";
        return 2;
    }
    App app(options, font);
    return app.run();
}

} // namespace carrom::client::app
