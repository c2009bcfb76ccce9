#pragma once
// The aim guide of practice and unrated games (room_state's aim_assist): for the shot a release
// would make now, the first piece the striker would touch, where, and the direction that piece
// would take, from the exact engine (carrom::first_contact) on the board the client holds. The
// answer for the same board and shot is kept, so a frame that changes neither costs nothing.

#include "carrom/client/snapshot.hpp"
#include "carrom/config.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/first_contact.hpp"
#include "carrom/rules/seat.hpp"
#include "carrom/scene.hpp"

#include <optional>
#include <span>
#include <vector>

namespace carrom::client {

class AimAssist {
public:
    explicit AimAssist(const PhysicsConfig& physics);

    // The first contact of `shot` from `side` on `board` (the board at rest; a striker in it is
    // replaced by the shot's, placed as the server's rules place it). nullopt when the striker
    // would touch nothing or the engine refuses the scene (an illegal placement).
    std::optional<FirstContact> guide(std::span<const BodyState> board, rules::Side side,
                                      const Shot& shot);
    int runs() const { return runs_; } // engine runs so far (a repeated question runs none)

private:
    PhysicsConfig physics_;
    ExactEngine engine_;
    std::vector<Body> scene_; // the last question's bodies, striker last
    std::optional<FirstContact> answer_;
    bool answered_ = false;
    int runs_ = 0;
};

} // namespace carrom::client
