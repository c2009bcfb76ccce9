#include "run_timeout.hpp"

#include <iostream>

namespace carrom::client::app {

void RunTimeout::on_frame(UnattendedFrame& frame) {
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    if (elapsed_s <= timeout_s_) {
        return;
    }
    std::cerr << "carrom-client: gave up after " << timeout_s_ << " s (" << frame.progress()
              << ")\n";
    done_ = 3;
}

} // namespace carrom::client::app
