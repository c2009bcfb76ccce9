#include "final_state_mode.hpp"

#include "carrom/client/board_report.hpp"
#include "window_output.hpp"

namespace carrom::client::app {

void FinalStateMode::on_frame(UnattendedFrame& frame) {
    if (frame.at_end) {
        done_ = write_final_state_file(path_,
                                       final_state_json(frame.model.view(), frame.model.board_now(),
                                                        frame.model.transcript()));
    }
}

} // namespace carrom::client::app
