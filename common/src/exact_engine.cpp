// The public face of the exact event-driven engine: ExactEngine::run validates a scene and runs
// the engine (engine_state.hpp lists the files of its parts), and simulate_exact wraps it.

#include "carrom/exact_engine.hpp"
#include "carrom/double_bits.hpp"

#include "engine_state.hpp"

#include <cstdint>

namespace carrom {

namespace {

// The overlap tolerance of validate_scene's default, px.
constexpr double kOverlapTolerancePx = 1e-9;

// Same bits: doubles compared by representation, so -0.0 differs from 0.0 and NaN from nothing.
bool same_body(const Body& a, const Body& b) {
    return a.id == b.id && a.kind == b.kind && a.pocketed == b.pocketed &&
           double_bits(a.pos_px.x) == double_bits(b.pos_px.x) &&
           double_bits(a.pos_px.y) == double_bits(b.pos_px.y) &&
           double_bits(a.vel_px_s.x) == double_bits(b.vel_px_s.x) &&
           double_bits(a.vel_px_s.y) == double_bits(b.vel_px_s.y);
}

} // namespace

// Bit i set: bodies[i] is bit for bit body i of the last validated scene (the same engine, so
// the same config and tolerance). 0 when the sizes differ or there are more than 64 bodies.
std::uint64_t ExactEngine::Impl::unchanged_since_validated(std::span<const Body> bodies) const {
    if (bodies.size() != validated.size() || bodies.size() > 64) {
        return 0;
    }
    std::uint64_t mask = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        mask |= static_cast<std::uint64_t>(same_body(bodies[i], validated[i])) << i;
    }
    return mask;
}

ExactEngine::ExactEngine(const PhysicsConfig& config) : impl_(std::make_unique<Impl>(config)) {}
ExactEngine::~ExactEngine() = default;

const PhysicsConfig& ExactEngine::config() const {
    return impl_->config;
}

ExactEngine::Outcome ExactEngine::run(std::span<const Body> bodies, const SimOptions& options) {
    // Bodies identical to those of the last scene that passed validation are known not to
    // overlap one another (a bot's search runs thousands of scenes that differ in the striker).
    const std::uint64_t unchanged = impl_->unchanged_since_validated(bodies);
    if (auto error = validate_scene(impl_->config, bodies, kOverlapTolerancePx, unchanged)) {
        impl_->validated.clear();
        impl_->resting_cached = 0;
        return {std::move(error), nullptr};
    }
    impl_->validated.assign(bodies.begin(), bodies.end());
    impl_->options = options;
    impl_->load(bodies);
    impl_->settle_initial_state(unchanged);
    impl_->run_events();
    impl_->finish();
    return {std::nullopt, &impl_->result};
}

SimulateResult simulate_exact(const PhysicsConfig& config, std::span<const Body> bodies,
                              const SimOptions& options) {
    ExactEngine engine(config);
    ExactEngine::Outcome outcome = engine.run(bodies, options);
    SimulateResult out;
    out.error = std::move(outcome.error);
    if (outcome.result) {
        out.result = *outcome.result;
    }
    return out;
}

} // namespace carrom
