#include "auto_player.hpp"

#include "carrom/bots/match_view.hpp"
#include "carrom/client/aim_gesture.hpp"

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

void AutoPlayer::on_frame(UnattendedFrame& frame) {
    if (frame.live == nullptr) {
        return;
    }
    const LiveTurn& live = *frame.live;
    const MatchView& v = frame.model.view();
    if (!busy() && live.aim.phase() == AimPhase::Idle && live.room && live.room->turn == v.turn &&
        live.room->phase == proto::Phase::Aiming && !live.shot_sent) {
        if (aimed_turn_ == v.turn) {
            strategy_->shot_refused(); // the last gesture of this turn made no shot
        }
        aimed_turn_ = v.turn;
        aim(*live.room, live.aim.striker_x(), live.aim.side(), frame.mapping, frame.physics);
    }
    if (busy()) {
        frame.input.push_back(events_[next_++]);
    }
}

void AutoPlayer::aim(const proto::RoomState& room, double striker_x, rules::Side side,
                     const ScreenMapping& mapping, const PhysicsConfig& physics) {
    bots::DecisionBudget budget;
    budget.time = std::chrono::milliseconds(200); // the window waits for the choice
    const Shot shot =
        strategy_->choose_shot(bots::match_state_from(room, physics), room.you, budget);
    events_.clear();
    next_ = 0;
    for (const GestureStep& step : shot_gesture(physics, AimConfig{}, side, striker_x, shot)) {
        switch (step.kind) {
        case GestureStep::Kind::Press:
            events_.push_back(mouse(sf::Event::MouseButtonPressed, mapping, step.board_px));
            break;
        case GestureStep::Kind::Move:
            events_.push_back(mouse(sf::Event::MouseMoved, mapping, step.board_px));
            break;
        case GestureStep::Kind::Release:
            events_.push_back(mouse(sf::Event::MouseButtonReleased, mapping, step.board_px));
            break;
        }
    }
}

} // namespace carrom::client::app
