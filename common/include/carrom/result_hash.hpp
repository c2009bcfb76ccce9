#pragma once
// A 64-bit FNV-1a hash over the bits of everything a run of the engine reports: every event
// (time, kind, bodies, impulse, position), every final body state, the end time and the pocket
// order. Two runs with the same hash gave bit-identical results (barring a hash collision), so
// it pins the engine's results (tests/common/exact_pinned_results_test.cpp) and compares builds
// (carrom-engine-runs, docs/physics.md "Speed"). Doubles are hashed by their bits: -0.0 and
// 0.0 differ.

#include "carrom/exact_engine.hpp"

#include <cstdint>

namespace carrom {

class ResultHash {
public:
    // Adds a whole run; runs added in turn give one hash of the sequence.
    void add(const SimResult& result);
    std::uint64_t value() const { return value_; }

private:
    void add_word(std::uint64_t word);
    void add_double(double x);
    void add_int(int x);

    std::uint64_t value_ = 1469598103934665603ULL; // the FNV-1a 64-bit offset basis
};

} // namespace carrom
