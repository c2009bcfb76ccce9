#include "app.hpp"

#include "board_painter.hpp"
#include "carrom/client/aim_controller.hpp"
#include "carrom/client/demo_link.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "draw_util.hpp"
#include "font.hpp"
#include "hud_painter.hpp"
#include "lobby_view.hpp"
#include "network_link.hpp"
#include "sound_player.hpp"
#include "text.hpp"

#include <SFML/Graphics.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
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
};

void print_bench(const FrameStats& s, unsigned w, unsigned h) {
    std::printf("{\"width\": %u, \"height\": %u, \"frames\": %zu, \"p50_ms\": %.3f, "
                "\"p99_ms\": %.3f, \"max_ms\": %.3f, \"moving_frames\": %zu, "
                "\"moving_p50_ms\": %.3f, \"moving_p99_ms\": %.3f}\n",
                w, h, s.all_ms.size(), percentile(s.all_ms, 0.5), percentile(s.all_ms, 0.99),
                percentile(s.all_ms, 1.0), s.moving_ms.size(), percentile(s.moving_ms, 0.5),
                percentile(s.moving_ms, 0.99));
}

class App {
public:
    App(const AppOptions& options, const sf::Font& font)
        : options_(options), font_(font), clock_(!options.screenshot_path.empty() ||
                                                 options.bench_frames > 0),
          geometry_(make_board_geometry(physics_)), model_(physics_), aim_(physics_),
          board_painter_(geometry_), hud_(font), lobby_(font),
          sound_(!options.mute && options.bench_frames == 0 && options.screenshot_path.empty()),
          session_(make_factory(), options.name) {}

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
            return std::make_unique<DemoLink>(physics, [this] { return clock_.now(); }, demo);
        };
    }
    void handle_event(const sf::Event& e);
    void handle_match_input(const sf::Event& e);
    void update(double now);
    void sync_aim(double now);
    void draw(double now);
    void draw_aim();
    void draw_status_panel(const std::string& title, const std::string& detail);
    bool save_screenshot();
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
    BoardPainter board_painter_;
    HudPainter hud_;
    LobbyView lobby_;
    SoundPlayer sound_;
    ClientSession session_;
    sf::RenderWindow window_;
    ScreenLayout layout_;
    std::vector<RenderedBody> bodies_;
    int aim_turn_ = -1;       // the turn the aim controller was set up for
    int shot_sent_turn_ = -1; // the turn we already shot in (no double shots)
    double last_aim_sent_s_ = -1.0;
    bool aim_dirty_ = false;
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
    if (model_.view().in_room) {
        handle_match_input(e);
    }
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
        } else if (e.key.code == sf::Keyboard::R &&
                   model_.view().phase == proto::Phase::GameOver) {
            session_.send_game(proto::Rematch{});
            model_.log().post("Rematch asked for", Tone::Info, clock_.now());
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
        if (session_.send_game(proto::Shoot{turn, shot->x_px, shot->angle_rad, shot->power})) {
            shot_sent_turn_ = turn;
            aim_.end_turn();
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
        if (std::holds_alternative<proto::Error>(m)) {
            shot_sent_turn_ = -1; // a rejected shot: aim again
        }
        model_.handle(m, now);
    }
    for (const ClientSession::PongSample& p : session_.take_pongs()) {
        model_.server_clock().round_trip(p.server_ms, p.sent_s, p.received_s);
    }
    sync_aim(now);
    bodies_ = model_.render(now);
    for (const SoundCue& cue : model_.take_sounds()) {
        sound_.play(cue);
    }
}

void App::draw_aim() {
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
            draw_text(window_, font_, "Power " + std::to_string(std::lround(100.0 * frac)) + "%",
                      static_cast<unsigned>(std::max(12.0, m.length_to_screen(11.0))),
                      f(label.x), f(label.y), sf::Color::White, Align::Centre);
        }
        board_painter_.draw_striker(window_, m, s, 1.0, !aim_.placement().legal);
        if (!aim_.placement().legal) {
            const Vec2 label = m.to_screen(s) +
                               Vec2{0.0, m.length_to_screen(physics_.striker_radius_px + 16.0)};
            draw_text(window_, font_, "Overlaps a piece",
                      static_cast<unsigned>(std::max(12.0, m.length_to_screen(10.0))),
                      f(label.x), f(label.y), sf::Color(255, 90, 80), Align::Centre);
        }
        return;
    }
    if (v.phase == proto::Phase::Aiming && !model_.animating() && v.to_play != v.you) {
        // The opponent's striker, where they are placing it.
        const double x = v.aim_x_px.value_or(physics_.centre().x);
        const Vec2 s{clamp_baseline_x(physics_, x), baseline_y(physics_, model_.seat_baseline(v.to_play))};
        board_painter_.draw_striker(window_, m, s, 0.85, false);
    }
}

void App::draw_status_panel(const std::string& title, const std::string& detail) {
    const Rect& b = layout_.board;
    draw_panel(window_, b, sf::Color(20, 12, 8, 200));
    const float cx = f(b.x + b.w / 2.0);
    draw_text(window_, font_, title, static_cast<unsigned>(std::clamp(b.h * 0.05, 18.0, 44.0)),
              cx, f(b.y + b.h * 0.42), sf::Color(236, 184, 64), Align::Centre);
    draw_text(window_, font_, detail, static_cast<unsigned>(std::clamp(b.h * 0.024, 12.0, 22.0)),
              cx, f(b.y + b.h * 0.52), sf::Color(242, 232, 214), Align::Centre);
}

void App::draw(double now) {
    window_.clear(sf::Color(28, 18, 12));
    const ScreenMapping m = mapping();
    board_painter_.draw_board(window_, m);
    const SessionPhase phase = session_.phase();
    if (model_.view().in_room) {
        board_painter_.draw_pieces(window_, m, bodies_);
        draw_aim();
        ConnectionLine line{session_.status_text(),
                            phase == SessionPhase::InRoom || phase == SessionPhase::Joining,
                            session_.rtt_ms()};
        hud_.draw(window_, layout_, model_, line, now);
        if (phase == SessionPhase::Reconnecting || phase == SessionPhase::Failed ||
            phase == SessionPhase::Connecting || phase == SessionPhase::Greeting) {
            draw_status_panel(phase == SessionPhase::Failed ? "Disconnected" : "Reconnecting",
                              session_.status_text());
        }
        return;
    }
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

bool App::save_screenshot() {
    sf::Texture shot;
    const sf::Vector2u size = window_.getSize();
    if (!shot.create(size.x, size.y)) {
        return false;
    }
    shot.update(window_);
    return shot.copyToImage().saveToFile(options_.screenshot_path);
}

int App::run() {
    sf::ContextSettings settings;
    settings.antialiasingLevel = 4;
    window_.create(sf::VideoMode(options_.width, options_.height),
                   "Carrom" + std::string(options_.demo ? " (demo)" : ""), sf::Style::Default,
                   settings);
    if (!window_.isOpen()) {
        std::cerr << "carrom-client: could not open a window (is DISPLAY set?)\n";
        return 1;
    }
    const bool fixed = !options_.screenshot_path.empty() || options_.bench_frames > 0;
    if (!fixed) {
        window_.setVerticalSyncEnabled(true);
        window_.setFramerateLimit(144);
    }
    const sf::Vector2u size = window_.getSize();
    window_.setView(sf::View(sf::FloatRect(0.0f, 0.0f, f(size.x), f(size.y))));
    layout_ = make_layout(size.x, size.y);
    if (options_.request) {
        session_.request(*options_.request);
    }
    session_.start(clock_.now());
    FrameStats stats;
    int frame = 0;
    constexpr int kWarmupFrames = 10;
    while (window_.isOpen()) {
        const auto t0 = std::chrono::steady_clock::now();
        sf::Event event;
        while (window_.pollEvent(event)) {
            handle_event(event);
        }
        const double now = clock_.now();
        update(now);
        draw(now);
        ++frame;
        if (!options_.screenshot_path.empty() && frame >= options_.frames) {
            const bool saved = save_screenshot();
            window_.close();
            if (!saved) {
                std::cerr << "carrom-client: could not save " << options_.screenshot_path << "\n";
                return 1;
            }
            std::cout << "saved " << options_.screenshot_path << "\n";
            return 0;
        }
        window_.display();
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        if (options_.bench_frames > 0 && frame > kWarmupFrames) {
            stats.all_ms.push_back(ms);
            if (model_.animating()) {
                stats.moving_ms.push_back(ms);
            }
            if (frame >= options_.bench_frames + kWarmupFrames) {
                window_.close();
                print_bench(stats, size.x, size.y);
                return 0;
            }
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
