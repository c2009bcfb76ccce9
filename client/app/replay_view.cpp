#include "replay_view.hpp"

#include "carrom/client/game_over_text.hpp"

#include "blitter.hpp"
#include "board_painter.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "draw_util.hpp"
#include "font.hpp"
#include "hud_painter.hpp"
#include "text.hpp"
#include "unattended_modes.hpp"
#include "window_output.hpp"

#include <SFML/Graphics.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>
#include <variant>
#include <vector>

namespace carrom::client::app {

namespace {

std::string speed_text(double speed) {
    char text[16];
    std::snprintf(text, sizeof text, "%gx", speed);
    return text;
}

class ReplayView {
public:
    ReplayView(const AppOptions& options, ReplayModel model, const sf::Font& font)
        : options_(options), replay_(std::move(model)), physics_(replay_.created().physics),
          hud_model_(physics_), board_painter_(make_board_geometry(physics_)), hud_(font) {
        replay_.set_speed(options.replay_speed);
        if (options.replay_at_s >= 0.0) {
            replay_.seek(options.replay_at_s);
            replay_.pause();
        }
    }

    int run();

private:
    // What the HUD shows changes at these points: an input's lead, its motion, its rest board.
    struct Shown {
        std::size_t turn = 0;
        int part = 0; // 0 lead, 1 motion, 2 rest, 3 the replay's end
        bool operator==(const Shown&) const = default;
    };
    Shown shown_at(double t) const;
    void handle(const sf::Event& e);
    void sync_hud(double now);
    int seat_count() const { return static_cast<int>(replay_.created().seats.size()); }
    ScreenMapping mapping() const { return make_mapping(layout_.board, physics_.board_size_px); }
    void draw(double now);
    std::string status() const;
    std::string progress() const;
    // Hands the frame just drawn (number `frame`) to the unattended mode; its exit code when it
    // ends the run.
    std::optional<int> unattended_frame(int frame);

    AppOptions options_;
    ReplayModel replay_;
    PhysicsConfig physics_;
    MatchModel hud_model_; // the HUD's view, fed what a spectator would have been told
    Blitter blitter_;
    BoardPainter board_painter_;
    HudPainter hud_;
    sf::RenderWindow window_;
    ScreenLayout layout_;
    std::optional<Shown> shown_;
    std::vector<RenderedBody> bodies_;           // the pieces drawn this frame
    int shots_seen_ = 0;                         // shot results given to hud_model_
    std::unique_ptr<UnattendedMode> unattended_; // null: none
    std::vector<sf::Event> unattended_input_;    // the mode's events for the next frame
};

ReplayView::Shown ReplayView::shown_at(double t) const {
    if (replay_.turns().empty() || t >= replay_.duration_s()) {
        return {replay_.turns().size(), 3};
    }
    const std::size_t i = replay_.turn_at(t);
    const ReplayTurn& turn = replay_.turns()[i];
    return {i, t < turn.motion_s ? 0 : (t < turn.rest_s ? 1 : 2)};
}

void ReplayView::handle(const sf::Event& e) {
    if (handle_window_event(window_, e, layout_, seat_count())) {
        return;
    }
    if (e.type != sf::Event::KeyPressed) {
        return;
    }
    switch (e.key.code) {
    case sf::Keyboard::Space:
        replay_.toggle_play();
        break;
    case sf::Keyboard::Right:
        replay_.next_turn();
        break;
    case sf::Keyboard::Left:
        replay_.previous_turn();
        break;
    case sf::Keyboard::Up:
    case sf::Keyboard::Add:
    case sf::Keyboard::Equal:
        replay_.faster();
        break;
    case sf::Keyboard::Down:
    case sf::Keyboard::Subtract:
    case sf::Keyboard::Hyphen:
        replay_.slower();
        break;
    case sf::Keyboard::Home:
        replay_.restart();
        break;
    case sf::Keyboard::Escape:
        window_.close();
        break;
    default:
        break;
    }
}

// The HUD follows the replay: where what is shown changes, the room state of that moment; when
// an input's motion ended since (in play or jumped over forwards), first the shot result and the
// rule events (fouls, queen, dues, board and game end) a spectator received then.
void ReplayView::sync_hud(double now) {
    const double t = replay_.time_s();
    const Shown shown = shown_at(t);
    if (shown_ && *shown_ == shown) {
        return;
    }
    const auto done = [](const Shown& s) { return s.part == 2 ? s.turn + 1 : s.turn; };
    if (!shown_) { // the first frame: from the start (--replay-at may open the replay anywhere)
        hud_model_.handle(replay_.room_state_at(0.0), now);
    } else if (done(shown) < done(*shown_)) {
        hud_model_.log().clear(); // back in time (Home, Left): later strokes' lines would mislead
    }
    // Only the newest outcome's messages when several were jumped over (the room state carries
    // the scores; older messages would only bury the board).
    if (done(shown) > (shown_ ? done(*shown_) : 0)) {
        for (const proto::ServerMessage& m : replay_.outcome_messages(done(shown) - 1)) {
            if (std::holds_alternative<proto::ShotResult>(m)) {
                ++shots_seen_;
            }
            hud_model_.handle(m, now);
        }
    }
    hud_model_.handle(replay_.room_state_at(t), now);
    shown_ = shown;
}

std::string ReplayView::status() const {
    // Every input is a turn: strokes, shot clock expiries and forfeits.
    std::string text = "Replay  \xc2\xb7  Turn " + std::to_string(replay_.turn_number()) + " / " +
                       std::to_string(replay_.turns().size()) + "  \xc2\xb7  ";
    if (replay_.finished()) { // the reason instead of the speed
        const MatchView& v = hud_model_.view();
        return text + (v.result ? "End: " + game_over_text(v, false).reason : std::string("End"));
    }
    text += speed_text(replay_.speed());
    if (!replay_.playing()) {
        text += "  \xc2\xb7  Paused";
    }
    return text;
}

std::string ReplayView::progress() const {
    std::ostringstream text;
    text << "replay at " << replay_.time_s() << " of " << replay_.duration_s() << " s";
    return text.str();
}

void ReplayView::draw(double now) {
    const ScreenMapping m = mapping();
    const Rect band{0.0, layout_.top_bar.h, layout_.top_bar.w,
                    layout_.seat_bar.y - layout_.top_bar.h};
    board_painter_.draw_board(window_, blitter_, m, band);
    bodies_.clear();
    for (const Body& b : replay_.bodies()) {
        if (!b.pocketed) {
            bodies_.push_back(RenderedBody{b.id, b.kind, b.pos_px, 1.0, 1.0, false});
        }
    }
    board_painter_.draw_pieces(window_, blitter_, m, bodies_);
    hud_model_.render(now); // only for the coins each seat has left (the pieces are the replay's)
    hud_.draw(window_, blitter_, layout_, hud_model_,
              ConnectionLine{status(), replay_.mismatches() == 0, std::nullopt, true}, now);
    const Rect& b = layout_.board;
    const auto size = static_cast<unsigned>(std::clamp(b.h * 0.022, 11.0, 18.0));
    hud_.texts().draw(window_,
                      "Space play/pause  \xc2\xb7  Left/Right stroke  \xc2\xb7  Up/Down speed  "
                      "\xc2\xb7  Home restart",
                      size, f(b.x + b.w / 2.0), f(b.y + b.h - size * 1.2), sf::Color(242, 232, 214),
                      Align::Centre);
}

std::optional<int> ReplayView::unattended_frame(int frame) {
    if (!unattended_) {
        return std::nullopt;
    }
    const ScreenMapping m = mapping();
    UnattendedFrame f{frame,
                      window_,
                      hud_model_,
                      nullptr,
                      replay_.finished(),
                      [this] { return progress(); },
                      shots_seen_,
                      m,
                      physics_,
                      bodies_,
                      std::nullopt,
                      hud_.overlay_area(),
                      std::nullopt,
                      board_painter_.repaints(),
                      hud_.bar_repaints(),
                      unattended_input_,
                      false};
    unattended_->on_frame(f);
    return unattended_->done();
}

int ReplayView::run() {
    window_.create(sf::VideoMode(options_.width, options_.height), "Carrom (replay)",
                   sf::Style::Default, sf::ContextSettings(0, 0, options_.msaa));
    if (!window_.isOpen()) {
        std::cerr << "carrom-client: could not open a window (is DISPLAY set?)\n";
        return 1;
    }
    window_.setVerticalSyncEnabled(true);
    window_.setFramerateLimit(144);
    const sf::Vector2u size = window_.getSize();
    window_.setView(sf::View(sf::FloatRect(0.0f, 0.0f, f(size.x), f(size.y))));
    layout_ = make_layout(size.x, size.y, seat_count(), true);
    unattended_ = make_replay_unattended_mode(options_);
    using Clock = std::chrono::steady_clock;
    const auto started = Clock::now();
    auto last = started;
    int frame = 0;
    while (window_.isOpen()) {
        sf::Event event;
        while (window_.pollEvent(event)) {
            handle(event);
        }
        for (const sf::Event& e : std::exchange(unattended_input_, {})) {
            handle(e);
        }
        const auto now_tp = Clock::now();
        replay_.advance(std::chrono::duration<double>(now_tp - last).count());
        last = now_tp;
        const double now = std::chrono::duration<double>(now_tp - started).count();
        sync_hud(now);
        draw(now);
        ++frame;
        if (const std::optional<int> code = unattended_frame(frame)) {
            window_.close();
            return *code;
        }
        window_.display();
    }
    return 0;
}

} // namespace

int run_replay(const AppOptions& options, ReplayModel model) {
    sf::Font font;
    std::string error;
    if (!load_font(font, error)) {
        std::cerr << "carrom-client: " << error << "\n";
        return 2;
    }
    ReplayView view(options, std::move(model), font);
    return view.run();
}

} // namespace carrom::client::app
