#include "carrom/golden/interpolation_cases.hpp"

#include "carrom/client/board_geometry.hpp"
#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/playout_clock.hpp"
#include "carrom/config.hpp"
#include "carrom/proto/codec.hpp"

#include <map>
#include <optional>
#include <set>

namespace carrom::golden {
namespace {

client::Snapshot snapshot_from(const nlohmann::json& j) {
    client::Snapshot s;
    s.seq = j.at("seq").get<std::uint64_t>();
    s.time_s = j.at("time").get<double>();
    s.keyframe = j.at("keyframe").get<bool>();
    for (const nlohmann::json& b : j.at("bodies")) {
        s.bodies.push_back({b.at(0).get<int>(), kind_named(b.at(1).get<std::string>()),
                            Vec2{b.at(2).get<double>(), b.at(3).get<double>()},
                            Vec2{b.at(4).get<double>(), b.at(5).get<double>()},
                            b.at(6).get<bool>()});
    }
    return s;
}

nlohmann::json body_json(int id, BodyKind kind, Vec2 pos, Vec2 vel, bool pocketed) {
    return {id, to_string(kind), pos.x, pos.y, vel.x, vel.y, pocketed};
}

// One turn's snapshots as the stream has them, with their arrival times (s).
struct TurnSnapshots {
    std::vector<proto::Snapshot> snapshots;
    std::vector<double> arrivals_s;
};

// The first room state's bodies and the snapshots of the first `turns` turns with motion.
struct StreamTurns {
    std::vector<proto::BoardBody> bodies;
    std::vector<TurnSnapshots> turns;
};

StreamTurns turns_of(const std::vector<StreamLine>& stream, int turns) {
    StreamTurns out;
    std::map<int, TurnSnapshots> by_turn;
    std::set<int> moving;
    for (const StreamLine& line : stream) {
        const auto decoded = proto::decode_server(line.text);
        if (!decoded.ok()) {
            continue;
        }
        if (const auto* room = std::get_if<proto::RoomState>(&*decoded.message)) {
            if (out.bodies.empty()) {
                out.bodies = room->bodies;
            }
        } else if (const auto* s = std::get_if<proto::Snapshot>(&*decoded.message)) {
            if (out.bodies.empty() || (s->keyframe && s->t_s <= 0.0)) {
                continue; // the board at rest: no motion to interpolate
            }
            if (!moving.count(s->turn) && static_cast<int>(moving.size()) >= turns) {
                continue;
            }
            moving.insert(s->turn);
            by_turn[s->turn].snapshots.push_back(*s);
            by_turn[s->turn].arrivals_s.push_back(line.at_s);
        }
    }
    for (auto& [turn, snapshots] : by_turn) {
        out.turns.push_back(std::move(snapshots));
    }
    return out;
}

} // namespace

nlohmann::json replay_interpolation(const nlohmann::json& input) {
    client::InterpolationBuffer buffer(client::make_board_geometry(PhysicsConfig{}));
    buffer.set_motion(input.at("motion").at("damping_per_s").get<double>(),
                      input.at("motion").at("every_change_sent").get<bool>());
    nlohmann::json out = nlohmann::json::array();
    for (const nlohmann::json& op : input.at("ops")) {
        if (op.contains("push")) {
            out.push_back(buffer.push(snapshot_from(op.at("push"))));
            continue;
        }
        nlohmann::json bodies = nlohmann::json::array();
        for (const client::RenderedBody& b : buffer.sample(op.at("sample").get<double>())) {
            bodies.push_back({b.id, rounded(b.pos_px.x), rounded(b.pos_px.y), rounded(b.scale),
                              rounded(b.alpha), b.falling});
        }
        out.push_back(bodies);
    }
    return out;
}

nlohmann::json replay_playout(const nlohmann::json& input) {
    client::PlayoutConfig config;
    config.interval_factor = input.at("interval_factor").get<double>();
    client::PlayoutClock clock(config);
    nlohmann::json out = nlohmann::json::array();
    for (const nlohmann::json& op : input.at("ops")) {
        if (op.contains("snapshot")) {
            clock.on_snapshot(op.at("snapshot").at(0).get<double>(),
                              op.at("snapshot").at(1).get<double>());
            out.push_back(nullptr);
        } else {
            out.push_back(rounded(clock.render_time(op.at("render").get<double>())));
        }
    }
    return out;
}

nlohmann::json interpolation_input(const std::vector<StreamLine>& stream, int turns,
                                   bool every_change_sent) {
    const StreamTurns st = turns_of(stream, turns);
    std::map<int, BodyKind> kinds;
    std::map<int, Vec2> last_pos;
    nlohmann::json keyframe_bodies = nlohmann::json::array();
    for (const proto::BoardBody& b : st.bodies) {
        kinds[b.id] = b.kind;
        last_pos[b.id] = b.pos_px;
        keyframe_bodies.push_back(body_json(b.id, b.kind, b.pos_px, b.vel_px_s, b.pocketed));
    }
    nlohmann::json ops = nlohmann::json::array();
    std::uint64_t seq = 1;
    ops.push_back(
        {{"push",
          {{"seq", seq++}, {"time", 0.0}, {"keyframe", true}, {"bodies", keyframe_bodies}}}});
    double previous = 0.0;
    double base = 1.0;
    for (const TurnSnapshots& turn : st.turns) {
        double last = base;
        for (const proto::Snapshot& s : turn.snapshots) {
            const double time = rounded(base + s.t_s);
            nlohmann::json bodies = nlohmann::json::array();
            for (const proto::SnapshotBody& b : s.bodies) {
                bodies.push_back(body_json(b.id, kinds[b.id], b.pos_px, b.vel_px_s, false));
                last_pos[b.id] = b.pos_px;
            }
            for (const int id : s.pocketed) {
                bodies.push_back(body_json(id, kinds[id], last_pos[id], {}, true));
            }
            ops.push_back(
                {{"push",
                  {{"seq", seq++}, {"time", time}, {"keyframe", s.keyframe}, {"bodies", bodies}}}});
            // Between the states around the drawn time, and a little past the newest.
            for (const double t : {previous + 0.4 * (time - previous), time + 0.03}) {
                ops.push_back({{"sample", rounded(t)}});
            }
            previous = time;
            last = time;
        }
        for (const double ahead : {0.05, 0.1, 0.2, 0.3}) {
            ops.push_back({{"sample", rounded(last + ahead)}});
        }
        base = last + 1.0;
    }
    return {{"motion",
             {{"damping_per_s", PhysicsConfig{}.damping_per_s},
              {"every_change_sent", every_change_sent}}},
            {"ops", ops}};
}

nlohmann::json playout_input(const std::vector<StreamLine>& stream, int turns) {
    const StreamTurns st = turns_of(stream, turns);
    nlohmann::json ops = nlohmann::json::array();
    double base = 1.0;
    for (const TurnSnapshots& turn : st.turns) {
        double last = base;
        for (std::size_t i = 0; i < turn.snapshots.size(); ++i) {
            const double time = rounded(base + turn.snapshots[i].t_s);
            const double local = turn.arrivals_s[i];
            ops.push_back({{"snapshot", {time, local}}});
            ops.push_back({{"render", rounded(local + 0.004)}});
            ops.push_back({{"render", rounded(local + 0.016)}});
            last = time;
        }
        base = last + 1.0;
    }
    return {{"interval_factor", client::PlayoutConfig{}.interval_factor}, {"ops", ops}};
}

} // namespace carrom::golden
