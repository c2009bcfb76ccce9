#include "carrom/client/sound_cue_queue.hpp"
#include "carrom/client/sound_cue_schedule.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace carrom::client {
namespace {

TEST(SoundCueQueue, ReleasesCuesInTimeOrderWhenDue) {
    SoundCueQueue q;
    q.push({0.30, SoundKind::Pocket, 1.0});
    q.push({0.10, SoundKind::Click, 0.5});
    q.push({0.20, SoundKind::Cushion, 0.7});
    q.push({std::nan(""), SoundKind::Click, 1.0}); // ignored
    EXPECT_EQ(q.size(), 3u);
    EXPECT_TRUE(q.take_due(0.05).empty());
    const auto due = q.take_due(0.25);
    ASSERT_EQ(due.size(), 2u);
    EXPECT_EQ(due[0].kind, SoundKind::Click);
    EXPECT_EQ(due[1].kind, SoundKind::Cushion);
    EXPECT_EQ(q.size(), 1u);
}

TEST(SoundCueQueue, StaleCuesAreDroppedNotPlayed) {
    SoundCueQueue q;
    q.push({1.0, SoundKind::Click, 1.0});
    q.push({4.9, SoundKind::Click, 1.0});
    const auto due = q.take_due(5.0, 0.25);
    ASSERT_EQ(due.size(), 1u);
    EXPECT_DOUBLE_EQ(due[0].time_s, 4.9);
    EXPECT_EQ(q.size(), 0u);
}

TEST(SoundCueQueue, HoldsAtMost512CuesAndDropsTheEarliest) {
    SoundCueQueue q;
    for (int i = 0; i < 600; ++i) {
        q.push({10.0 + i * 0.001, SoundKind::Click, 1.0});
    }
    EXPECT_EQ(q.size(), 512u);
    // A cue earlier than all that wait goes in and straight out again.
    q.push({1.0, SoundKind::Pocket, 1.0});
    EXPECT_EQ(q.size(), 512u);
    const auto due = q.take_due(100.0, 1e9);
    ASSERT_EQ(due.size(), 512u);
    EXPECT_EQ(due.front(), (SoundCue{10.0 + 88 * 0.001, SoundKind::Click, 1.0}));
    EXPECT_EQ(due.back(), (SoundCue{10.0 + 599 * 0.001, SoundKind::Click, 1.0}));
}

TEST(SoundCueQueue, ASmallerCapacityDropsTheEarliestCue) {
    SoundCueQueue q(2);
    q.push({0.2, SoundKind::Click, 0.5});
    q.push({0.1, SoundKind::Cushion, 0.5});
    q.push({0.3, SoundKind::Pocket, 0.5});
    EXPECT_EQ(q.take_due(1.0, 1.0),
              (std::vector<SoundCue>{{0.2, SoundKind::Click, 0.5}, {0.3, SoundKind::Pocket, 0.5}}));
}

TEST(SoundCueSchedule, CuesOfOneKindAtTheSameMillisecondAreOneCueTheLoudest) {
    SoundCueSchedule s;
    s.add(4, 0.1000, SoundKind::Click, 0.4, 2.0);
    s.add(4, 0.1002, SoundKind::Click, 0.9, 2.0);   // the same ms as 2.1: merged, louder
    s.add(4, 0.1001, SoundKind::Cushion, 0.3, 2.0); // another kind: its own cue
    s.add(4, 0.1003, SoundKind::Click, 0.9, 2.0);   // as loud: the first stays
    s.add(4, 0.1020, SoundKind::Click, 0.2, 2.0);   // 2 ms later: its own cue
    s.render_to(2.2);
    EXPECT_EQ(s.take(), (std::vector<SoundCue>{{2.0 + 0.1002, SoundKind::Click, 0.9},
                                               {2.0 + 0.1001, SoundKind::Cushion, 0.3},
                                               {2.0 + 0.1020, SoundKind::Click, 0.2}}));
    EXPECT_TRUE(s.take().empty()); // each cue once
}

TEST(SoundCueSchedule, CuesMergeOnlyWithinOneTake) {
    SoundCueSchedule s;
    s.add(1, 0.5, SoundKind::Pocket, 0.5, 0.0);
    s.render_to(0.6);
    EXPECT_EQ(s.take(), (std::vector<SoundCue>{{0.5, SoundKind::Pocket, 0.5}}));
    s.add(1, 0.5, SoundKind::Pocket, 1.0, 0.0);
    s.render_to(0.6);
    EXPECT_EQ(s.take(), (std::vector<SoundCue>{{0.5, SoundKind::Pocket, 1.0}}));
}

TEST(SoundCueSchedule, AtMost256CuesWaitForTheirShotsStartAndTheOldestGo) {
    SoundCueSchedule s;
    for (int i = 0; i <= 256; ++i) { // 1 ms apart: none merge
        s.add(7, i * 0.001, SoundKind::Click, 1.0, std::nullopt);
    }
    s.render_to(100.0);
    EXPECT_TRUE(s.take().empty()); // the shot's start is not known
    s.start(7, 10.0);
    s.render_to(10.1);
    const std::vector<SoundCue> first = s.take();
    ASSERT_EQ(first.size(), 100u); // t = 1 .. 100 ms: the cue at t = 0 was dropped
    EXPECT_EQ(first.front(), (SoundCue{10.0 + 0.001, SoundKind::Click, 1.0}));
    s.render_to(10.3);
    EXPECT_EQ(s.take().size(), 156u);
}

TEST(SoundCueSchedule, WaitingCuesArePlacedAtTheirShotsStart) {
    SoundCueSchedule s;
    s.add(3, 0.25, SoundKind::Cushion, 0.7, std::nullopt);
    s.add(4, 0.10, SoundKind::Click, 0.5, std::nullopt);
    s.start(3, 20.0);
    s.render_to(20.3);
    EXPECT_EQ(s.take(), (std::vector<SoundCue>{{20.25, SoundKind::Cushion, 0.7}}));
    s.start(4, 30.0);
    s.render_to(30.2);
    EXPECT_EQ(s.take(), (std::vector<SoundCue>{{30.1, SoundKind::Click, 0.5}}));
}

TEST(SoundCueSchedule, PredictedCuesPlayAsTheDrawnTimePassesThem) {
    SoundCueSchedule s;
    s.set_predicted({{1.0, SoundKind::Click, 0.5}, {1.5, SoundKind::Pocket, 1.0}});
    s.render_to(1.2);
    EXPECT_EQ(s.take(), (std::vector<SoundCue>{{1.0, SoundKind::Click, 0.5}}));
    s.drop_predicted();
    s.render_to(2.0);
    EXPECT_TRUE(s.take().empty());
}

} // namespace
} // namespace carrom::client
