#include "screenshot_mode.hpp"

#include "carrom/client/board_report.hpp"
#include "window_output.hpp"

#include <fstream>
#include <iostream>

namespace carrom::client::app {

void ScreenshotMode::on_frame(UnattendedFrame& frame) {
    if (due(frame)) {
        done_ = save(frame);
    }
}

bool ScreenshotMode::due(const UnattendedFrame& frame) const {
    if (frame.number < frames_ || frame.input_pending || (board_summary_ && !frame.board_summary) ||
        (game_over_ && !frame.at_end)) {
        return false;
    }
    // The card between boards names the next board's colours once its room_state arrived (it
    // follows the board_end event, possibly in a later frame).
    const auto& summary = frame.model.view().board_summary;
    if (board_summary_ && summary && frame.model.view().board_number <= summary->board) {
        return false;
    }
    return after_shots_ <= 0 || (frame.shots_seen >= after_shots_ && !frame.model.animating());
}

int ScreenshotMode::save(const UnattendedFrame& frame) const {
    if (!save_window_png(frame.window, path_)) {
        std::cerr << "carrom-client: could not save " << path_ << "\n";
        return 1;
    }
    if (!report_path_.empty()) {
        const sf::Vector2u size = frame.window.getSize();
        std::ofstream out(report_path_);
        std::vector<RenderedBody> drawn = frame.bodies;
        if (frame.aim_striker) {
            drawn.push_back(
                RenderedBody{-1, BodyKind::Striker, *frame.aim_striker, 1.0, 1.0, false});
        }
        const ReportContext context{static_cast<double>(size.x),
                                    static_cast<double>(size.y),
                                    frame.shots_seen,
                                    frame.overlay,
                                    frame.model.prediction_stats(),
                                    frame.ui,
                                    &frame.model.transcript()};
        out << board_report_json(frame.model.view(), drawn, frame.mapping, context) << "\n";
        if (!out) {
            std::cerr << "carrom-client: could not write " << report_path_ << "\n";
            return 1;
        }
    }
    std::cout << "saved " << path_ << std::endl;
    return 0;
}

} // namespace carrom::client::app
