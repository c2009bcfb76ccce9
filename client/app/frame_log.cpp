#include "frame_log.hpp"

#include <nlohmann/json.hpp>

#include <chrono>

namespace carrom::client::app {

std::optional<std::string> FrameLog::open(const std::string& path) {
    out_.open(path, std::ios::out | std::ios::trunc);
    if (!out_) {
        return "--frame-log: cannot write " + path;
    }
    return std::nullopt;
}

double FrameLog::now_ms() {
    const auto since = std::chrono::steady_clock::now().time_since_epoch();
    return std::chrono::duration<double, std::milli>(since).count();
}

void FrameLog::shoot(const proto::Shoot& shoot, bool predicted) {
    if (!out_.is_open()) {
        return;
    }
    const nlohmann::json line{{"ms", now_ms()},           {"kind", "shoot"},
                              {"turn", shoot.turn},       {"x", shoot.x_px},
                              {"angle", shoot.angle_rad}, {"power", shoot.power},
                              {"predicted", predicted}};
    out_ << line.dump() << '\n' << std::flush;
}

void FrameLog::frame(long index, const MatchModel& model, const std::vector<RenderedBody>& drawn,
                     SessionPhase link) {
    if (!out_.is_open()) {
        return;
    }
    const double render_s = model.rendered_time_s();
    const MatchModel::ShotTime shot = model.shot_time(render_s);
    nlohmann::json bodies = nlohmann::json::array();
    for (const RenderedBody& b : drawn) {
        if (!b.falling) {
            bodies.push_back({b.id, b.pos_px.x, b.pos_px.y});
        }
    }
    const nlohmann::json line{{"ms", now_ms()},
                              {"kind", "frame"},
                              {"frame", index},
                              {"render_s", render_s},
                              {"turn", shot.turn},
                              {"t", shot.t_s},
                              {"predicted", model.prediction().active()},
                              {"delay_ms", 1000.0 * model.playout().delay_s()},
                              {"playing", model.animating()},
                              {"link", std::string(net::session_phase_name(link))},
                              {"bodies", std::move(bodies)}};
    out_ << line.dump() << '\n' << std::flush;
}

} // namespace carrom::client::app
