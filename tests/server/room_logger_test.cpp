// A room's notices as the operator reads them: info-level log lines.
#include "room_logger.hpp"

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <memory>
#include <sstream>

namespace carrom::server {
namespace {

// Sends spdlog's default logger to a string (message and level only) for one test.
class CapturedLog {
public:
    CapturedLog() : previous_(spdlog::default_logger()) {
        auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(out_);
        sink->set_pattern("%l %v");
        auto logger = std::make_shared<spdlog::logger>("captured", sink);
        logger->set_level(spdlog::level::info);
        spdlog::set_default_logger(logger);
    }
    ~CapturedLog() { spdlog::set_default_logger(previous_); }
    CapturedLog(const CapturedLog&) = delete;
    CapturedLog& operator=(const CapturedLog&) = delete;

    std::string text() const { return out_.str(); }

private:
    std::ostringstream out_;
    std::shared_ptr<spdlog::logger> previous_;
};

TEST(RoomLogger, MembersAndGameEndsAreLoggedAtInfo) {
    CapturedLog log;
    RoomLogger logger("K7MXQ2");
    logger.member({room::MembershipChange::Joined, "Asha", 0, false});
    logger.member({room::MembershipChange::Joined, "Bot (medium)", 1, true});
    logger.member({room::MembershipChange::Joined, "Cy", -1, false});
    logger.member({room::MembershipChange::Dropped, "Asha", 0, false});
    logger.member({room::MembershipChange::Returned, "Asha", 0, false});
    logger.game_over({0, "score", {25, 7}});
    logger.member({room::MembershipChange::Left, "Cy", -1, false});
    logger.game_over({-1, "boards", {9, 9}});
    EXPECT_EQ(log.text(), "info room K7MXQ2: player Asha (seat 0) joined\n"
                          "info room K7MXQ2: bot Bot (medium) (seat 1) joined\n"
                          "info room K7MXQ2: spectator Cy joined\n"
                          "info room K7MXQ2: player Asha (seat 0) dropped; the seat waits for "
                          "the grace period\n"
                          "info room K7MXQ2: player Asha (seat 0) returned\n"
                          "info room K7MXQ2: game over, seat 0 won (score), scores 25-7\n"
                          "info room K7MXQ2: spectator Cy left\n"
                          "info room K7MXQ2: game over, no winner (boards), scores 9-9\n");
}

} // namespace
} // namespace carrom::server
