#pragma once
// carrom-client --frame-log FILE: one JSON object per line for each frame drawn in a room and
// each shot sent, stamped with the monotonic clock (CLOCK_MONOTONIC, ms), the clock of
// carrom-bot --trace, so that scripts/network_report.py lines the client's screen up with a
// bot's shots and the server's exact trajectory (carrom-sim --frame-error). docs/client-frames.md,
// "Frame log".

#include "carrom/client/client_session.hpp"
#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/proto/client_messages.hpp"

#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace carrom::client::app {

class FrameLog {
public:
    // Opens (truncates) path; the error sentence when it cannot.
    std::optional<std::string> open(const std::string& path);
    bool is_open() const { return out_.is_open(); }

    // {"ms":..,"kind":"shoot","turn":..,"x":..,"angle":..,"power":..,"predicted":bool}
    void shoot(const proto::Shoot& shoot, bool predicted);
    // {"ms":..,"kind":"frame","frame":N,"render_s":..,"turn":T,"t":..,"predicted":bool,
    //  "delay_ms":..,"playing":bool,"link":"..","bodies":[[id,x,y],...]}: the bodies drawn on
    // the board (not pocketed, not falling), board px; link: the session's phase.
    void frame(long index, const MatchModel& model, const std::vector<RenderedBody>& drawn,
               SessionPhase link);

private:
    static double now_ms();
    std::ofstream out_;
};

} // namespace carrom::client::app
