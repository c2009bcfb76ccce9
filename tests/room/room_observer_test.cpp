// What the room tells its observer (the server's log): members joining, dropping, returning and
// leaving, and how each game ended.
#include "room/room_fixture.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace carrom::room {
namespace {

using testing::RoomTest;
using testing::ScriptedBrain;

// Records what the room tells its observer, one line per notice.
class RecordingObserver final : public RoomObserver {
public:
    void member(const MemberNotice& n) override {
        static constexpr const char* kChange[] = {"joined", "dropped", "returned", "left"};
        lines.push_back(std::string(kChange[static_cast<int>(n.change)]) + " " + n.name + " " +
                        std::to_string(n.seat) + (n.bot ? " bot" : ""));
    }
    void game_over(const proto::GameEndEvent& end) override {
        std::string line = "game over " + std::to_string(end.winner) + " " + end.reason;
        for (const int score : end.scores) {
            line += " " + std::to_string(score);
        }
        lines.push_back(line);
    }
    std::vector<std::string> lines;
};

TEST_F(RoomTest, TheObserverHearsMembersAndGameEnds) {
    RecordingObserver observer;
    Room room("ABCDEF", config(), clock_, counters_, &observer);
    ASSERT_FALSE(room.join(a_, proto::Role::Player));
    ASSERT_FALSE(room.seat_bot("Bot", std::make_shared<ScriptedBrain>()));
    ASSERT_FALSE(room.join(watcher_, proto::Role::Spectator));
    room.disconnected(*a_);
    ASSERT_FALSE(room.resume(a_));
    room.leave(*watcher_);
    room.leave(*a_); // forfeits the running game
    EXPECT_EQ(observer.lines,
              (std::vector<std::string>{"joined Asha 0", "joined Bot 1 bot", "joined Cy -1",
                                        "dropped Asha 0", "returned Asha 0", "left Cy -1",
                                        "left Asha 0", "game over 1 left 0 0"}));
}

TEST_F(RoomTest, TheObserverHearsWhenTheGracePeriodEnds) {
    RecordingObserver observer;
    Room room("ABCDEF", config(), clock_, counters_, &observer);
    ASSERT_FALSE(room.join(a_, proto::Role::Player));
    ASSERT_FALSE(room.join(b_, proto::Role::Player));
    room.disconnected(*b_);
    clock_.advance_ms(60000);
    room.tick();
    EXPECT_EQ(observer.lines,
              (std::vector<std::string>{"joined Asha 0", "joined Bo 1", "dropped Bo 1", "left Bo 1",
                                        "game over 0 forfeit 0 0"}));
}

} // namespace
} // namespace carrom::room
