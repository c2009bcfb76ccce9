#pragma once
// Skill levels: how precisely a bot executes the shot it chose. A level is Gaussian noise on
// the angle (radians) and on the power (a fraction of the chosen power); the striker position is
// placed exactly (so a legal placement stays legal). Deterministic for a seeded generator.

#include "carrom/scene.hpp"

#include <optional>
#include <random>
#include <string_view>

namespace carrom::bots {

enum class SkillLevel { Perfect, Hard, Medium, Easy };

struct ExecutionNoise {
    double angle_sigma_rad = 0.0;      // standard deviation of the angle error, rad
    double power_sigma_fraction = 0.0; // standard deviation of the power error / chosen power
};

// The noise of each level: perfect 0; hard 0.3 deg, 2 %; medium 1.5 deg, 6 %; easy 4 deg, 12 %.
ExecutionNoise noise_of(SkillLevel level);

// "perfect", "hard", "medium", "easy".
std::string_view to_string(SkillLevel level);
std::optional<SkillLevel> parse_skill_level(std::string_view text);

// The shot as executed: angle + N(0, angle_sigma), power * (1 + N(0, power_sigma)) clamped to
// [0, max_power]; x unchanged. With zero noise the shot is returned unchanged and rng untouched.
Shot execute_with_noise(const Shot& intended, const ExecutionNoise& noise, double max_power,
                        std::mt19937_64& rng);

} // namespace carrom::bots
