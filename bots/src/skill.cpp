#include "carrom/bots/skill.hpp"

#include "carrom/enum_names.hpp"

#include <algorithm>
#include <numbers>

namespace carrom::bots {

namespace {
constexpr double kDegToRad = std::numbers::pi / 180.0;
} // namespace

ExecutionNoise noise_of(SkillLevel level) {
    switch (level) {
    case SkillLevel::Perfect:
        return {0.0, 0.0};
    case SkillLevel::Hard:
        return {0.3 * kDegToRad, 0.02};
    case SkillLevel::Medium:
        return {1.5 * kDegToRad, 0.06};
    case SkillLevel::Easy:
        return {4.0 * kDegToRad, 0.12};
    }
    return {};
}

namespace {
constexpr enum_names::Table<SkillLevel, 4> kSkillLevelNames{{
    {SkillLevel::Perfect, "perfect"},
    {SkillLevel::Hard, "hard"},
    {SkillLevel::Medium, "medium"},
    {SkillLevel::Easy, "easy"},
}};
} // namespace

std::string_view to_string(SkillLevel level) {
    return enum_names::name_of(kSkillLevelNames, level).value_or("perfect");
}

std::optional<SkillLevel> parse_skill_level(std::string_view text) {
    return enum_names::parse(kSkillLevelNames, text);
}

Shot execute_with_noise(const Shot& intended, const ExecutionNoise& noise, double max_power,
                        std::mt19937_64& rng) {
    Shot shot = intended;
    if (noise.angle_sigma_rad > 0.0) {
        std::normal_distribution<double> angle_error(0.0, noise.angle_sigma_rad);
        shot.angle_rad += angle_error(rng);
    }
    if (noise.power_sigma_fraction > 0.0) {
        std::normal_distribution<double> power_error(0.0, noise.power_sigma_fraction);
        shot.power = std::clamp(shot.power * (1.0 + power_error(rng)), 0.0, max_power);
    }
    return shot;
}

} // namespace carrom::bots
