#include "carrom/golden/model_cases.hpp"

#include "carrom/proto/codec.hpp"
#include "carrom/rules/seat.hpp"

#include <string>

namespace carrom::golden {
namespace {

// The web client's names, by the enums' order (Tone: Info, Good, Foul, Error; SoundKind: Click,
// Cushion, Pocket).
std::string tone_name(client::Tone tone) {
    static constexpr const char* kNames[] = {"info", "good", "foul", "error"};
    return kNames[static_cast<std::size_t>(tone)];
}

std::string sound_name(client::SoundKind kind) {
    static constexpr const char* kNames[] = {"click", "cushion", "pocket"};
    return kNames[static_cast<std::size_t>(kind)];
}

} // namespace

nlohmann::json view_json(const client::MatchModel& model) {
    const client::MatchView& v = model.view();
    if (!v.in_room) {
        return {{"in_room", false}}; // the rest is the defaults of each client's own
    }
    nlohmann::json seats = nlohmann::json::array();
    for (const client::SeatView& s : v.seats) {
        seats.push_back({{"occupied", s.occupied},
                         {"name", s.name},
                         {"connected", s.connected},
                         {"bot", s.bot},
                         {"colour", proto::to_string(s.colour)},
                         {"side", rules::to_string(s.side)},
                         {"score", s.score},
                         {"dues", s.dues}});
    }
    nlohmann::json result = nullptr;
    if (v.result) {
        result = {{"winner", v.result->winner}, {"reason", game_end_name(*v.result)}};
    }
    return {{"in_room", v.in_room},
            {"code", v.code},
            {"you", v.you},
            {"rule_set", proto::to_string(v.rule_set)},
            {"options",
             {{"target_points", v.options.target_points},
              {"boards", v.options.boards},
              {"shot_clock_s", v.options.shot_clock_s}}},
            {"seats", seats},
            {"spectators", v.spectators},
            {"board_number", v.board_number},
            {"turn", v.turn},
            {"to_play", v.to_play},
            {"phase", proto::to_string(v.phase)},
            {"queen", {{"state", proto::to_string(v.queen.state)}, {"seat", v.queen.seat}}},
            {"winner", v.winner},
            {"deadline_ms", v.deadline_ms ? nlohmann::json(*v.deadline_ms) : nullptr},
            {"aim_x", v.aim_x_px ? nlohmann::json(rounded(*v.aim_x_px)) : nullptr},
            {"result", result}};
}

nlohmann::json model_steps(const std::vector<StreamLine>& stream) {
    client::MatchModel model(PhysicsConfig{});
    nlohmann::json steps = nlohmann::json::array();
    nlohmann::json last_view;
    for (const StreamLine& line : stream) {
        nlohmann::json step = nlohmann::json::object();
        const auto decoded = proto::decode_server(line.text);
        if (decoded.ok()) {
            model.handle(*decoded.message, line.at_s);
        } else {
            step["refused"] = decoded.error.code;
        }
        nlohmann::json view = view_json(model);
        if (view != last_view) {
            step["view"] = view;
            last_view = std::move(view);
        }
        nlohmann::json log = nlohmann::json::array();
        for (const client::HudLine& l : model.log().all()) {
            log.push_back({l.text, tone_name(l.tone)});
        }
        model.log() = client::HudLog(); // the next step shows only its own lines
        if (!log.empty()) {
            step["log"] = log;
        }
        model.render(line.at_s);
        step["render_s"] = rounded(model.rendered_time_s());
        nlohmann::json sounds = nlohmann::json::array();
        for (const client::SoundCue& c : model.take_sounds()) {
            sounds.push_back({sound_name(c.kind), rounded(c.time_s), rounded(c.volume)});
        }
        if (!sounds.empty()) {
            step["sounds"] = sounds;
        }
        steps.push_back(std::move(step));
    }
    return steps;
}

std::vector<StreamLine> cue_stream(const std::vector<StreamLine>& recorded) {
    std::vector<StreamLine> out;
    int turn = -1;
    for (const StreamLine& line : recorded) {
        out.push_back(line);
        const auto decoded = proto::decode_server(line.text);
        const auto* s = decoded.ok() ? std::get_if<proto::Snapshot>(&*decoded.message) : nullptr;
        if (s != nullptr && !s->keyframe) {
            turn = s->turn;
            break;
        }
    }
    if (turn < 0) {
        return out;
    }
    const double at = out.back().at_s;
    for (int k = 0; k < 200; ++k) {
        const double t = 0.1 + 0.006 * k;
        const double impulse = 50.0 + 7.0 * (k % 13);
        out.push_back(
            {at, proto::encode(proto::Event{proto::CollisionEvent{turn, t, 1, 2, impulse}})});
        out.push_back(
            {at, proto::encode(proto::Event{proto::CollisionEvent{turn, t, 3, 4, impulse * 1.5}})});
        out.push_back({at, proto::encode(proto::Event{
                               proto::CushionEvent{turn, t + 0.003, 5, k % 4, impulse * 2.0}})});
    }
    std::int64_t nonce = 1;
    for (const double later : {0.05, 0.2, 0.35, 0.5, 0.8, 1.0, 1.5, 2.0}) {
        out.push_back({at + later, proto::encode(proto::Pong{nonce++, 0})});
    }
    return out;
}

} // namespace carrom::golden
