#pragma once
// The C API between the web page and the exact engine (common/) built to WebAssembly
// (docs/web.md, "The engine in the page"). Plain C functions over numbers and buffers of doubles
// in the module's linear memory, so the page reads results through Float64Array views instead of
// parsing text. The same file is compiled natively (library carrom_engine_api), so the
// determinism test compares the two builds through one code path.
//
// One engine instance per module (per page or Web Worker): carrom_simulate keeps the last stroke
// (its trajectory, events and final bodies) until the next call. Not thread-safe.
//
// Units: board px, px/s, seconds, radians; the physics is PhysicsConfig's defaults (the server's).
// Body records (carrom_scene, carrom_frame): 5 doubles: id, kind (0 black, 1 white, 2 queen,
// 3 striker), x_px, y_px, pocketed (0 or 1). Final records (carrom_final): 7 doubles: id, kind,
// x_px, y_px, vx_px_s, vy_px_s, pocketed. Event records (carrom_events): 7 doubles: t_s, kind
// (0 collision, 1 cushion, 2 pocket, 3 stop), a, b, impulse, x_px, y_px (carrom/event.hpp).

#include <cstdint>

extern "C" {

// Most pieces a scene may hold (the striker added by carrom_simulate included).
inline constexpr int kCarromMaxBodies = 64;

// kPhysicsVersion (carrom/physics_version.hpp): a match journal of another version is refused.
int carrom_physics_version();

// The input buffer: up to kCarromMaxBodies - 1 body records (5 doubles each) written by the
// caller before carrom_simulate or carrom_first_contact.
double* carrom_scene();

// Simulates a stroke: the first body_count records of carrom_scene (any striker among them is
// dropped) plus the striker placed as the server's rules place it (rules::striker_for) for side
// (0 bottom, 1 right, 2 top, 3 left) and the shot (x_px along the baseline, angle_rad, power),
// with events and trajectory recorded. Returns 0, or -1 when the engine refuses the scene
// (carrom_error names why) or the input is out of range (code "bad_input"); nothing is kept then.
int carrom_simulate(int body_count, int side, double x_px, double angle_rad, double power);

// The refused scene's error code ("overlap", "outside_cushions", "bad_input", ...), a
// NUL-terminated string in linear memory; "" after a success.
const char* carrom_error();

// The last stroke: bodies in the result (sorted by id, the striker last), their final records,
// events (time order), the time of the last event, and its ResultHash (carrom/result_hash.hpp)
// as two 32-bit halves (JS numbers hold 53 bits).
int carrom_body_count();
const double* carrom_final();
int carrom_event_count();
const double* carrom_events();
double carrom_end_time_s();
std::uint32_t carrom_result_hash_high();
std::uint32_t carrom_result_hash_low();

// Every body of the last stroke at shot time t_s (state_at, carrom/trajectory.hpp) as body
// records in carrom_frame, in carrom_final's order; returns the count (0 without a stroke).
int carrom_state_at(double t_s);
const double* carrom_frame();

// For an aim assist: simulates like carrom_simulate (replacing the last stroke) and returns the
// id of the first piece the striker touches, or -1 when it touches none (or the scene is refused).
// carrom_contact then holds 5 doubles: the contact's time (s), the striker's centre at the
// contact (x_px, y_px) and the unit direction the piece moves in just after it (x, y).
int carrom_first_contact(int body_count, int side, double x_px, double angle_rad, double power);
const double* carrom_contact();

} // extern "C"
