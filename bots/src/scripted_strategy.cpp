#include "carrom/bots/scripted_strategy.hpp"

#include "carrom/bots/shot_geometry.hpp"
#include "carrom/proto/limits.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace carrom::bots {

namespace {

// Reads a finite number field in [lo, hi] or says why not.
std::optional<std::string> read_number(const nlohmann::json& line, const char* key, double lo,
                                       double hi, double& out) {
    const auto it = line.find(key);
    if (it == line.end()) {
        return std::string("missing field '") + key + "'";
    }
    if (!it->is_number()) {
        return std::string("field '") + key + "' must be a number";
    }
    const double value = it->get<double>();
    if (!std::isfinite(value) || value < lo || value > hi) {
        return std::string("field '") + key + "' must be a number in [" + std::to_string(lo) +
               ", " + std::to_string(hi) + "]";
    }
    out = value;
    return std::nullopt;
}

std::optional<std::string> read_shot(std::string_view text, Shot& shot) {
    const auto line = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
    if (line.is_discarded()) {
        return std::string("not valid JSON");
    }
    if (!line.is_object()) {
        return std::string("must be a JSON object {\"x\", \"angle\", \"power\"}");
    }
    if (auto e = read_number(line, "x", 0.0, proto::kMaxCoordinatePx, shot.x_px)) {
        return e;
    }
    if (auto e =
            read_number(line, "angle", -proto::kMaxAngleRad, proto::kMaxAngleRad, shot.angle_rad)) {
        return e;
    }
    return read_number(line, "power", 0.0, PhysicsConfig{}.max_power, shot.power);
}

} // namespace

std::variant<std::vector<Shot>, std::string> parse_script(std::string_view text) {
    std::vector<Shot> shots;
    int line_number = 0;
    while (!text.empty()) {
        const auto end = text.find('\n');
        std::string_view line = text.substr(0, end);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
        ++line_number;
        while (!line.empty() &&
               (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) {
            line.remove_suffix(1);
        }
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string_view::npos || line[first] == '#') {
            continue;
        }
        Shot shot;
        if (auto error = read_shot(line, shot)) {
            return "line " + std::to_string(line_number) + ": " + *error + ".";
        }
        shots.push_back(shot);
    }
    if (shots.empty()) {
        return std::string("The script has no shots.");
    }
    return shots;
}

ScriptedStrategy::ScriptedStrategy(std::vector<Shot> shots) : shots_(std::move(shots)) {
    if (shots_.empty()) {
        shots_.push_back(Shot{});
    }
}

Shot ScriptedStrategy::choose_shot(const rules::MatchState& state, int seat,
                                   const DecisionBudget& /*budget*/) {
    if (nudge_ > 0) {
        next_ = (next_ + shots_.size() - 1) % shots_.size(); // the refused shot again, moved
    }
    Shot shot = shots_[next_ % shots_.size()];
    next_ = (next_ + 1) % shots_.size();
    shot.x_px += 3.0 * static_cast<double>(nudge_); // a refusal the rules did not foresee
    nudge_ = 0;
    if (!shot_is_legal(state, seat, shot)) {
        shot.x_px = nearest_legal_x(state, seat, shot.x_px).value_or(shot.x_px);
    }
    return shot;
}

} // namespace carrom::bots
