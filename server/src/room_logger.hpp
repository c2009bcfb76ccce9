#pragma once
// Private to server/src: a room's notices (room::RoomObserver) as info-level log lines, so an
// operator sees the server work: who joined, dropped, returned or left which seat, and how each
// game ended.

#include "carrom/room/room_observer.hpp"

#include <string>

namespace carrom::server {

class RoomLogger final : public room::RoomObserver {
public:
    explicit RoomLogger(std::string code) : code_(std::move(code)) {}

    void member(const room::MemberNotice& notice) override;
    void game_over(const proto::GameEndEvent& end) override;

private:
    std::string code_;
};

} // namespace carrom::server
