#include "auto_player.hpp"

#include "carrom/bots/match_view.hpp"
#include "carrom/client/aim_controller.hpp"
#include "carrom/scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace carrom::client::app {
namespace {

sf::Event mouse(sf::Event::EventType type, const ScreenMapping& mapping, Vec2 board_px) {
    const Vec2 s = mapping.to_screen(board_px);
    sf::Event e{};
    e.type = type;
    const auto x = static_cast<int>(std::lround(s.x));
    const auto y = static_cast<int>(std::lround(s.y));
    if (type == sf::Event::MouseMoved) {
        e.mouseMove = {x, y};
    } else {
        e.mouseButton = {sf::Mouse::Left, x, y};
    }
    return e;
}

} // namespace

AutoPlayer::AutoPlayer(proto::BotLevel level, std::uint64_t seed)
    : strategy_(bots::make_level_strategy(level, seed)) {}

std::optional<sf::Event> AutoPlayer::next_event() {
    if (!busy()) {
        return std::nullopt;
    }
    return events_[next_++];
}

void AutoPlayer::aim(const proto::RoomState& room, double striker_x, Baseline baseline,
                     const ScreenMapping& mapping, const PhysicsConfig& physics) {
    bots::DecisionBudget budget;
    budget.time = std::chrono::milliseconds(200); // the window waits for the choice
    const Shot shot =
        strategy_->choose_shot(bots::match_state_from(room, physics), room.you, budget);
    const double y = baseline_y(physics, baseline);
    const double x = clamp_baseline_x(physics, shot.x_px);
    std::vector<sf::Event>& events = events_;
    events.clear();
    next_ = 0;
    // Slide: press in the baseline band away from the striker (a press on it would pull).
    const double far = striker_x > physics.centre().x ? 113.0 : 487.0;
    events.push_back(mouse(sf::Event::MouseButtonPressed, mapping, {far, y}));
    events.push_back(mouse(sf::Event::MouseMoved, mapping, {(far + x) / 2.0, y}));
    events.push_back(mouse(sf::Event::MouseMoved, mapping, {x, y}));
    events.push_back(mouse(sf::Event::MouseButtonReleased, mapping, {x, y}));
    // Pull back from the striker: the shot goes from the pointer towards the striker, its power
    // from the pull's length (the aim controller's inverse).
    const AimConfig aim_config;
    const double power = std::clamp(shot.power, 0.0, physics.max_power);
    const double drag = aim_config.dead_zone_px +
                        std::max(power / physics.max_power *
                                     (aim_config.full_power_drag_px - aim_config.dead_zone_px),
                                 1.0);
    const Vec2 dir{std::cos(shot.angle_rad), std::sin(shot.angle_rad)};
    const Vec2 striker{x, y};
    events.push_back(mouse(sf::Event::MouseButtonPressed, mapping, striker));
    for (const double k : {0.25, 0.5, 0.75, 1.0}) {
        events.push_back(mouse(sf::Event::MouseMoved, mapping, striker - dir * (drag * k)));
    }
    events.push_back(mouse(sf::Event::MouseButtonReleased, mapping, striker - dir * drag));
}

} // namespace carrom::client::app
