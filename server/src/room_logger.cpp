#include "room_logger.hpp"

#include <spdlog/spdlog.h>

namespace carrom::server {

namespace {

// "player Asha (seat 0)", "bot Bot (medium) (seat 1)", "spectator Cy".
std::string who(const room::MemberNotice& notice) {
    if (notice.seat < 0) {
        return "spectator " + notice.name;
    }
    return (notice.bot ? "bot " : "player ") + notice.name + " (seat " +
           std::to_string(notice.seat) + ")";
}

} // namespace

void RoomLogger::member(const room::MemberNotice& notice) {
    switch (notice.change) {
    case room::MembershipChange::Joined:
        spdlog::info("room {}: {} joined", code_, who(notice));
        break;
    case room::MembershipChange::Dropped:
        spdlog::info("room {}: {} dropped; the seat waits for the grace period", code_,
                     who(notice));
        break;
    case room::MembershipChange::Returned:
        spdlog::info("room {}: {} returned", code_, who(notice));
        break;
    case room::MembershipChange::Left:
        spdlog::info("room {}: {} left", code_, who(notice));
        break;
    }
}

void RoomLogger::game_over(const proto::GameEndEvent& end) {
    std::string scores;
    for (const int score : end.scores) {
        scores += scores.empty() ? "" : "-";
        scores += std::to_string(score);
    }
    if (end.winner < 0) {
        spdlog::info("room {}: game over, no winner ({}), scores {}", code_, end.reason, scores);
    } else {
        spdlog::info("room {}: game over, seat {} won ({}), scores {}", code_, end.winner,
                     end.reason, scores);
    }
}

} // namespace carrom::server
