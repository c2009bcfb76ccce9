#include "final_state_mode.hpp"

#include "carrom/client/board_report.hpp"
#include "window_output.hpp"

namespace carrom::client::app {

void FinalStateMode::on_frame(UnattendedFrame& frame) {
    const MatchView& v = frame.model.view();
    if (!v.in_room || v.phase != proto::Phase::GameOver || !v.result || frame.model.animating()) {
        return;
    }
    done_ = write_final_state_file(path_, final_state_json(v, frame.model.board_now()));
}

} // namespace carrom::client::app
