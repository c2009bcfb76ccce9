#include "carrom/wasm/engine_api.h"

#include "api_error.hpp"

#include "carrom/exact_engine.hpp"
#include "carrom/physics_version.hpp"
#include "carrom/result_hash.hpp"
#include "carrom/rules/placement.hpp"
#include "carrom/trajectory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace {

constexpr std::size_t kSceneFields = 5;
constexpr std::size_t kFinalFields = 7;
constexpr std::size_t kEventFields = 7;
constexpr std::size_t kMaxBodies = static_cast<std::size_t>(kCarromMaxBodies);

// The module's one engine and what its last stroke left (see engine_api.h).
struct EngineApiState {
    carrom::PhysicsConfig physics{};
    carrom::ExactEngine engine{physics};
    std::array<double, kMaxBodies * kSceneFields> scene{};
    std::string error;
    std::vector<carrom::Body> order; // the simulated bodies, in input order
    carrom::Trajectory trajectory;
    std::vector<double> final_records;
    std::vector<double> event_records;
    std::vector<double> frame_records;
    std::vector<carrom::Event> events;
    double end_time_s = 0.0;
    std::uint64_t hash = 0;
    std::array<double, 5> contact{};
};

EngineApiState& api() {
    static EngineApiState state;
    return state;
}

bool read_kind(double value, carrom::BodyKind& kind) {
    if (!(value >= 0.0 && value <= 3.0) || value != std::floor(value)) {
        return false;
    }
    kind = static_cast<carrom::BodyKind>(static_cast<int>(value));
    return true;
}

// The scene's pieces sorted by id, then the striker for the shot; false on bad input.
bool build_bodies(EngineApiState& s, int body_count, int side, const carrom::Shot& shot,
                  std::vector<carrom::Body>& bodies) {
    if (body_count < 0 || static_cast<std::size_t>(body_count) >= kMaxBodies || side < 0 ||
        side > 3) {
        return false;
    }
    bodies.clear();
    for (std::size_t i = 0; i < static_cast<std::size_t>(body_count); ++i) {
        const double* r = &s.scene[i * kSceneFields];
        carrom::Body b;
        if (!read_kind(r[1], b.kind) || !(std::abs(r[0]) < 1e6) || r[0] != std::floor(r[0])) {
            return false;
        }
        b.id = static_cast<int>(r[0]);
        b.pos_px = {r[2], r[3]};
        b.pocketed = r[4] != 0.0;
        if (b.id != carrom::kStrikerId && b.kind != carrom::BodyKind::Striker) {
            bodies.push_back(b);
        }
    }
    std::sort(bodies.begin(), bodies.end(),
              [](const carrom::Body& a, const carrom::Body& b) { return a.id < b.id; });
    bodies.push_back(
        carrom::rules::striker_for(s.physics, static_cast<carrom::rules::Side>(side), shot));
    return true;
}

void forget_stroke(EngineApiState& s, std::string error) {
    s.error = std::move(error);
    s.order.clear();
    s.trajectory = {};
    s.final_records.clear();
    s.event_records.clear();
    s.events.clear();
    s.end_time_s = 0.0;
    s.hash = 0;
}

void keep_stroke(EngineApiState& s, const std::vector<carrom::Body>& bodies,
                 const carrom::SimResult& result) {
    s.error.clear();
    s.order = bodies;
    s.trajectory = result.trajectory;
    s.events = result.events;
    s.end_time_s = result.end_time_s;
    carrom::ResultHash hash;
    hash.add(result);
    s.hash = hash.value();
    s.final_records.clear();
    for (const carrom::Body& b : result.bodies) {
        s.final_records.insert(s.final_records.end(),
                               {static_cast<double>(b.id), static_cast<double>(b.kind), b.pos_px.x,
                                b.pos_px.y, b.vel_px_s.x, b.vel_px_s.y, b.pocketed ? 1.0 : 0.0});
    }
    s.event_records.clear();
    for (const carrom::Event& e : result.events) {
        s.event_records.insert(s.event_records.end(),
                               {e.t_s, static_cast<double>(e.kind), static_cast<double>(e.a),
                                static_cast<double>(e.b), e.impulse, e.pos_px.x, e.pos_px.y});
    }
}

} // namespace

void carrom::wasm::set_api_error(std::string_view code) {
    api().error = code;
}

extern "C" {

int carrom_physics_version() {
    return carrom::kPhysicsVersion;
}

double* carrom_scene() {
    return api().scene.data();
}

int carrom_simulate(int body_count, int side, double x_px, double angle_rad, double power) {
    EngineApiState& s = api();
    std::vector<carrom::Body> bodies;
    if (!build_bodies(s, body_count, side, carrom::Shot{x_px, angle_rad, power}, bodies)) {
        forget_stroke(s, "bad_input");
        return -1;
    }
    carrom::SimOptions options;
    options.record_events = true;
    options.record_trajectory = true;
    const carrom::ExactEngine::Outcome outcome = s.engine.run(bodies, options);
    if (outcome.error) {
        forget_stroke(s, outcome.error->code);
        return -1;
    }
    keep_stroke(s, bodies, *outcome.result);
    return 0;
}

const char* carrom_error() {
    return api().error.c_str();
}

int carrom_body_count() {
    return static_cast<int>(api().order.size());
}

const double* carrom_final() {
    return api().final_records.data();
}

int carrom_event_count() {
    return static_cast<int>(api().events.size());
}

const double* carrom_events() {
    return api().event_records.data();
}

double carrom_end_time_s() {
    return api().end_time_s;
}

std::uint32_t carrom_result_hash_high() {
    return static_cast<std::uint32_t>(api().hash >> 32U);
}

std::uint32_t carrom_result_hash_low() {
    return static_cast<std::uint32_t>(api().hash & 0xFFFFFFFFU);
}

int carrom_state_at(double t_s) {
    EngineApiState& s = api();
    s.frame_records.clear();
    if (s.order.empty()) {
        return 0;
    }
    for (const carrom::Body& b : carrom::state_at(s.physics, s.trajectory, t_s)) {
        s.frame_records.insert(s.frame_records.end(),
                               {static_cast<double>(b.id), static_cast<double>(b.kind), b.pos_px.x,
                                b.pos_px.y, b.pocketed ? 1.0 : 0.0});
    }
    return static_cast<int>(s.frame_records.size() / kSceneFields);
}

const double* carrom_frame() {
    return api().frame_records.data();
}

int carrom_first_contact(int body_count, int side, double x_px, double angle_rad, double power) {
    EngineApiState& s = api();
    s.contact = {};
    if (carrom_simulate(body_count, side, x_px, angle_rad, power) != 0) {
        return -1;
    }
    for (const carrom::Event& e : s.events) {
        if (e.kind != carrom::EventKind::Collision ||
            (e.a != carrom::kStrikerId && e.b != carrom::kStrikerId)) {
            continue;
        }
        const int piece = e.a == carrom::kStrikerId ? e.b : e.a;
        const auto index =
            static_cast<int>(std::find_if(s.order.begin(), s.order.end(),
                                          [&](const carrom::Body& b) { return b.id == piece; }) -
                             s.order.begin());
        // The piece's first segment at the contact's time holds its velocity just after it.
        carrom::Vec2 velocity{};
        for (const carrom::Segment& segment : s.trajectory.segments) {
            if (segment.index == index && segment.t_s >= e.t_s) {
                velocity = segment.vel_px_s;
                break;
            }
        }
        const double speed = carrom::length(velocity);
        const carrom::Vec2 striker = carrom::state_at(s.physics, s.trajectory, e.t_s).back().pos_px;
        s.contact = {e.t_s, striker.x, striker.y, speed > 0.0 ? velocity.x / speed : 0.0,
                     speed > 0.0 ? velocity.y / speed : 0.0};
        return piece;
    }
    return -1;
}

const double* carrom_contact() {
    return api().contact.data();
}

} // extern "C"
