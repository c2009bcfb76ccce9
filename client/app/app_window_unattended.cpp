#include "app_window.hpp"

#include "carrom/client/board_report.hpp"
#include "window_output.hpp"

#include <fstream>
#include <iostream>

namespace carrom::client::app {

// --autoplay: one queued mouse event per frame; on our turn, at rest, with the striker idle and
// the room state of this turn, the strategy aims (again, differently, when the last gesture of
// this turn made no shot or the server refused it).
void AppWindow::autoplay() {
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
    auto_player_->aim(*room_, aim_.striker_x(), aim_.side(), mapping(), physics_);
}

bool AppWindow::final_state_due() const {
    return !options_.final_state_path.empty() && model_.view().in_room &&
           model_.view().phase == proto::Phase::GameOver && model_.view().result &&
           !model_.animating();
}

int AppWindow::write_final_state() {
    return write_final_state_file(options_.final_state_path,
                                  final_state_json(model_.view(), model_.board_now()));
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

bool AppWindow::screenshot_due(int frame) const {
    if (options_.screenshot_path.empty() || frame < options_.frames) {
        return false;
    }
    return options_.after_shots <= 0 ||
           (shots_seen_ >= options_.after_shots && !model_.animating());
}

int AppWindow::finish_screenshot() {
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
                                    shots_seen_, hud_.overlay_area(), model_.prediction_stats()};
        out << board_report_json(model_.view(), drawn, mapping(), context) << "\n";
        if (!out) {
            std::cerr << "carrom-client: could not write " << options_.report_path << "\n";
            return 1;
        }
    }
    std::cout << "saved " << options_.screenshot_path << std::endl;
    return 0;
}

bool AppWindow::save_screenshot() {
    return save_window_png(window_, options_.screenshot_path);
}

bool AppWindow::timed_out(std::chrono::steady_clock::time_point started) const {
    if (options_.timeout_s <= 0.0 ||
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() <=
            options_.timeout_s) {
        return false;
    }
    std::cerr << "carrom-client: gave up after " << options_.timeout_s << " s ("
              << session_.status_text() << ", " << shots_seen_ << " shots seen)\n";
    return true;
}

// Records one frame's times for --bench-frames; prints the statistics and returns true after
// the last one.
bool AppWindow::bench_done(int frame, double ms, double cpu_ms) {
    if (!bench_.record(frame, ms, cpu_ms, model_.animating())) {
        return false;
    }
    const sf::Vector2u size = window_.getSize();
    std::cout << bench_.json({size.x, size.y, options_.msaa, board_painter_.repaints(),
                              hud_.bar_repaints()})
              << std::endl;
    return true;
}

} // namespace carrom::client::app
