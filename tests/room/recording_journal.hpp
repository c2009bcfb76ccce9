#pragma once
// A JournalSink that keeps every journal in memory, for the room tests: the journals by match id,
// the seat holders' tokens, and the confirmations the room waits for (answered by the test).

#include "carrom/proto/journal.hpp"
#include "carrom/room/journal_sink.hpp"
#include "carrom/room/room.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace carrom::room::testing {

class RecordingJournal final : public JournalSink {
public:
    std::string next_match_id() override { return "m" + std::to_string(++ids_); }
    void created(const proto::MatchCreated& created) override {
        EXPECT_TRUE(proto::is_match_id(created.match_id));
        EXPECT_EQ(journals.count(created.match_id), 0U);
        order.push_back(created.match_id);
        journals[created.match_id].created = created;
    }
    void append(const std::string& match_id, std::int64_t seq, const proto::JournalEntry& entry,
                bool confirm) override {
        ASSERT_EQ(journals.count(match_id), 1U) << match_id;
        auto& journal = journals[match_id];
        EXPECT_EQ(seq, static_cast<std::int64_t>(journal.entries.size())) << match_id;
        journal.entries.push_back(entry);
        if (confirm) {
            waiting.emplace_back(match_id, seq);
        }
    }
    void seat_holder(const std::string& match_id, int seat, const std::string& token) override {
        tokens[{match_id, seat}] = token;
    }
    void abandoned(const std::string& match_id) override { abandoned_ids.push_back(match_id); }

    // Answers every confirmation the room waits for.
    void confirm_all(Room& room) {
        auto answers = std::move(waiting);
        waiting.clear();
        for (const auto& [id, seq] : answers) {
            room.journal_written(id, seq);
        }
    }

    std::map<std::string, proto::MatchJournal> journals;
    std::vector<std::string> order; // match ids as created
    std::vector<std::pair<std::string, std::int64_t>> waiting;
    std::map<std::pair<std::string, int>, std::string> tokens;
    std::vector<std::string> abandoned_ids;

private:
    int ids_ = 0;
};

} // namespace carrom::room::testing
