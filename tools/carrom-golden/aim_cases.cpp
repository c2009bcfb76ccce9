#include "carrom/golden/aim_cases.hpp"

#include "carrom/client/aim_controller.hpp"
#include "carrom/client/aim_gesture.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "carrom/golden/golden_json.hpp"
#include "carrom/rules/seat.hpp"
#include "carrom/scene.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace carrom::golden {
namespace {

using client::AimController;
using client::BodyState;

// The web client's names, by AimPhase's order (Inactive, Idle, Sliding, Pulling).
std::string phase_name(client::AimPhase phase) {
    static constexpr const char* kNames[] = {"inactive", "idle", "sliding", "pulling"};
    return kNames[static_cast<std::size_t>(phase)];
}

client::ScreenMapping mapping_from(const nlohmann::json& v) {
    client::ScreenMapping m;
    m.origin_x = v.at("origin_x").get<double>();
    m.origin_y = v.at("origin_y").get<double>();
    m.scale = v.at("scale").get<double>();
    m.board_size_px = v.at("board_size").get<double>();
    m.bottom = static_cast<rules::Side>(v.at("turns").get<int>());
    return m;
}

Vec2 point_of(const nlohmann::json& p) {
    return {p.at(0).get<double>(), p.at(1).get<double>()};
}

nlohmann::json screen_point(const client::ScreenMapping& m, Vec2 board) {
    const Vec2 s = m.to_screen(board);
    return {rounded(s.x), rounded(s.y)};
}

std::vector<BodyState> standard_pieces() {
    std::vector<BodyState> out;
    for (const Body& b : standard_layout(PhysicsConfig{})) {
        if (b.kind != BodyKind::Striker) {
            out.push_back({b.id, b.kind, b.pos_px, {}, false});
        }
    }
    return out;
}

nlohmann::json pieces_json(const std::vector<BodyState>& pieces) {
    nlohmann::json out = nlohmann::json::array();
    for (const BodyState& b : pieces) {
        out.push_back({b.id, to_string(b.kind), b.pos_px.x, b.pos_px.y, b.pocketed});
    }
    return out;
}

// The absolute angle from a side's baseline straight at the board's centre.
double inward_angle(rules::Side side) {
    switch (side) {
    case rules::Side::Right:
        return std::numbers::pi;
    case rules::Side::Top:
        return std::numbers::pi / 2.0;
    case rules::Side::Left:
        return 0.0;
    case rules::Side::Bottom:
        break;
    }
    return -std::numbers::pi / 2.0;
}

nlohmann::json gesture(const std::string& name, double start_x,
                       const std::vector<BodyState>& pieces, nlohmann::json events) {
    return {{"name", name},
            {"start_x", start_x},
            {"pieces", pieces_json(pieces)},
            {"events", std::move(events)}};
}

} // namespace

nlohmann::json replay_aim(const nlohmann::json& input) {
    const client::ScreenMapping mapping = mapping_from(input.at("view"));
    rules::Side side = rules::Side::Bottom;
    rules::parse_side(input.at("side").get<std::string>(), side);
    const PhysicsConfig physics;
    nlohmann::json out = nlohmann::json::array();
    for (const nlohmann::json& g : input.at("gestures")) {
        std::vector<BodyState> pieces;
        for (const nlohmann::json& p : g.at("pieces")) {
            pieces.push_back({p.at(0).get<int>(),
                              kind_named(p.at(1).get<std::string>()),
                              Vec2{p.at(2).get<double>(), p.at(3).get<double>()},
                              {},
                              p.at(4).get<bool>()});
        }
        AimController aim(physics);
        aim.begin_turn(side, g.at("start_x").get<double>());
        nlohmann::json steps = nlohmann::json::array();
        for (const nlohmann::json& e : g.at("events")) {
            nlohmann::json shot = nullptr;
            const bool up = e.contains("up");
            if (e.contains("down")) {
                aim.pointer_down(mapping.to_board(point_of(e.at("down"))), pieces);
            } else if (e.contains("move")) {
                aim.pointer_move(mapping.to_board(point_of(e.at("move"))), pieces);
            } else if (up) {
                if (const auto s = aim.pointer_up(mapping.to_board(point_of(e.at("up"))), pieces)) {
                    shot = {rounded(s->x_px), rounded(s->angle_rad), rounded(s->power)};
                }
            } else if (e.contains("nudge")) {
                aim.nudge(e.at("nudge").at(0).get<int>(), e.at("nudge").at(1).get<bool>(), pieces);
            } else {
                aim.cancel();
            }
            nlohmann::json step = {{"phase", phase_name(aim.phase())},
                                   {"x", rounded(aim.striker_x())},
                                   {"legal", aim.placement().legal},
                                   {"blocking", aim.placement().blocking_id},
                                   {"moved", aim.take_moved()}};
            if (up) {
                step["shot"] = shot;
            }
            steps.push_back(std::move(step));
        }
        out.push_back({{"name", g.at("name")}, {"steps", steps}});
    }
    return out;
}

nlohmann::json aim_input(const std::string& side_name) {
    rules::Side side = rules::Side::Bottom;
    rules::parse_side(side_name, side);
    const PhysicsConfig physics;
    const client::AimConfig aim;
    const client::ScreenLayout layout = client::make_layout(900.0, 800.0, 4);
    const client::ScreenMapping m = client::make_mapping(layout.board, physics.board_size_px, side);
    const std::vector<BodyState> pieces = standard_pieces();
    const double start = physics.board_size_px / 2.0;
    const double a0 = inward_angle(side);
    auto on_screen = [&](Vec2 board) { return screen_point(m, board); };
    auto at = [&](double along) { return client::baseline_point(physics, side, along); };

    nlohmann::json gestures = nlohmann::json::array();
    // Shots made as carrom-client --autoplay makes them: slide, then pull.
    const Shot shots[] = {{200.0, a0, 12.0},
                          {420.0, a0 + 0.35, 25.0},
                          {300.0, a0 - 0.5, 3.0},
                          {90.0, a0 + 0.1, 40.0}};
    int n = 0;
    for (const Shot& shot : shots) {
        nlohmann::json events = nlohmann::json::array();
        for (const client::GestureStep& s : client::shot_gesture(physics, aim, side, start, shot)) {
            const char* kind = s.kind == client::GestureStep::Kind::Press     ? "down"
                               : s.kind == client::GestureStep::Kind::Release ? "up"
                                                                              : "move";
            events.push_back({{kind, on_screen(s.board_px)}});
        }
        gestures.push_back(gesture("shot " + std::to_string(++n), start, pieces, events));
    }
    // A pull inside the dead zone, then one across the whole board (capped at max power).
    const Vec2 striker = at(start);
    const Vec2 back{std::cos(a0) * -1.0, std::sin(a0) * -1.0};
    gestures.push_back(gesture("dead zone", start, pieces,
                               {{{"down", on_screen(striker)}},
                                {{"move", on_screen(striker + back * 5.0)}},
                                {{"up", on_screen(striker + back * 11.0)}},
                                {{"down", on_screen(striker + Vec2{3.0, -2.0})}},
                                {{"move", on_screen(striker + back * 300.0)}},
                                {{"up", on_screen(striker + back * 400.0)}}}));
    // A coin on the baseline: sliding onto it is illegal and a pull there shoots nothing.
    std::vector<BodyState> blocked = pieces;
    blocked.push_back({40, BodyKind::Black, at(220.0), {}, false});
    blocked.push_back({41, BodyKind::White, at(380.0), {}, true}); // pocketed: no obstacle
    gestures.push_back(gesture("blocked", start, blocked,
                               {{{"down", on_screen(at(480.0))}},
                                {{"move", on_screen(at(225.0) + back * 20.0)}},
                                {{"up", on_screen(at(225.0))}},
                                {{"down", on_screen(at(225.0))}},
                                {{"move", on_screen(at(225.0) + back * 90.0)}},
                                {{"up", on_screen(at(225.0) + back * 90.0)}},
                                {{"nudge", {1, true}}},
                                {{"nudge", {1, true}}},
                                {{"down", on_screen(at(380.0))}},
                                {{"up", on_screen(at(380.0))}}}));
    // Keys, a cancelled pull, presses away from the baseline and past the baseline's ends.
    gestures.push_back(gesture("keys and cancel", 150.0, pieces,
                               {{{"nudge", {-1, false}}},
                                {{"nudge", {-1, true}}},
                                {{"nudge", {-1, true}}},
                                {{"nudge", {1, false}}},
                                {{"down", on_screen(at(130.0))}},
                                {{"move", on_screen(at(130.0) + back * 60.0)}},
                                {{"cancel", true}},
                                {{"up", on_screen(at(130.0) + back * 60.0)}},
                                {{"down", on_screen(physics.centre())}},
                                {{"up", on_screen(physics.centre())}},
                                {{"down", on_screen(at(450.0) + back * -30.0)}},
                                {{"move", on_screen(at(700.0))}},
                                {{"up", on_screen(at(-50.0))}}}));
    return {{"view",
             {{"origin_x", m.origin_x},
              {"origin_y", m.origin_y},
              {"scale", m.scale},
              {"board_size", m.board_size_px},
              {"turns", static_cast<int>(side)}}},
            {"side", side_name},
            {"gestures", gestures}};
}

} // namespace carrom::golden
