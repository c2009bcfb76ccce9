#pragma once
// --autoplay LEVEL: plays our turns unattended with the bots library's strategy (the server
// bots' choice: greedy search at the skill level easy, medium or hard, or random). It chooses
// only the shot a player would aim, from the room state the server sent; the shot is made with
// the mouse events a player would make (press in the baseline band and slide the striker to its
// x, then press on the striker and pull back), handled by the same input path, so the aim
// controller checks it as any other and the server checks it as any other shot.

#include "unattended_mode.hpp"

#include "carrom/bots/strategy.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "carrom/config.hpp"
#include "carrom/proto/server_messages.hpp"
#include "carrom/proto/types.hpp"
#include "carrom/rules/seat.hpp"

#include <SFML/Window/Event.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace carrom::client::app {

class AutoPlayer final : public UnattendedMode {
public:
    AutoPlayer(proto::BotLevel level, std::uint64_t seed);

    // One queued mouse event per frame; on our turn, at rest, with the striker idle and the room
    // state of this turn, the strategy aims (again, differently, when the last gesture of this
    // turn made no shot or the server refused it). Nothing without a live turn (a replay).
    void on_frame(UnattendedFrame& frame) override;
    std::optional<int> done() const override { return std::nullopt; } // plays until another ends

private:
    // Chooses the shot for our seat in `room` (our turn, the board at rest, the striker idle at
    // striker_x along the baseline of `side`) and queues the mouse events (window px through the
    // turned view's `mapping`) that slide the striker to the chosen x and shoot it
    // (aim_gesture.hpp).
    void aim(const proto::RoomState& room, double striker_x, rules::Side side,
             const ScreenMapping& mapping, const PhysicsConfig& physics);
    bool busy() const { return next_ < events_.size(); }

    std::unique_ptr<bots::Strategy> strategy_;
    std::vector<sf::Event> events_; // handed out one per frame, so the window shows the aim
    std::size_t next_ = 0;
    int aimed_turn_ = -1; // the turn the strategy last aimed in
};

} // namespace carrom::client::app
