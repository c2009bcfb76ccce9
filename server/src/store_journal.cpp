#include "store_journal.hpp"

#include <algorithm>
#include <chrono>

namespace carrom::server {

StoreJournal::StoreJournal(std::shared_ptr<store::MatchStore> store, RandomSource& random,
                           const std::atomic<bool>& stopping, const std::atomic<bool>& rated,
                           IdentityOf identity_of)
    : store_(std::move(store)), random_(random), stopping_(stopping), rated_(rated),
      identity_of_(std::move(identity_of)) {}

std::string StoreJournal::next_match_id() {
    static constexpr char kDigits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
    std::string id;
    for (int part = 0; part < 2; ++part) {
        std::uint64_t bits = random_.next_u64();
        for (int i = 0; i < 8; ++i) {
            id.push_back(kDigits[bits % 36]);
            bits /= 36;
        }
    }
    return id;
}

void StoreJournal::created(const proto::MatchCreated& created) {
    store_->create(created);
    // Singles without a bot seat only (the server refuses a rated flag otherwise).
    const bool bot_seat = std::any_of(created.seats.begin(), created.seats.end(),
                                      [](const proto::JournalSeat& seat) { return seat.bot; });
    rating_match_ =
        rated_.load() && created.seats.size() == 2 && !bot_seat ? created.match_id : std::string{};
}

void StoreJournal::append(const std::string& match_id, std::int64_t seq,
                          const proto::JournalEntry& entry, bool confirm) {
    if (!confirm || !written_) {
        store_->append(match_id, seq, entry);
        return;
    }
    store_->append(match_id, seq, entry,
                   [written = written_, match_id, seq](bool) { written(match_id, seq); });
}

void StoreJournal::seat_holder(const std::string& match_id, int seat, const std::string& token) {
    std::optional<store::TokenHash> hash;
    if (!token.empty()) {
        hash = store::hash_token(token);
    }
    store_->set_seat_token(match_id, seat, hash);
    // Room::start_game names every seat right after created(): those holders are the rated ones.
    if (match_id == rating_match_ && identity_of_ && !token.empty()) {
        if (const auto player = identity_of_(token)) {
            store_->set_rated_seat(match_id, seat, *player);
        }
    }
    if (match_id == rating_match_ && seat == 1) {
        rating_match_.clear();
    }
}

void StoreJournal::abandoned(const std::string& match_id) {
    if (stopping_.load()) {
        return;
    }
    const auto now = std::chrono::system_clock::now().time_since_epoch();
    store_->mark_finished(match_id,
                          std::chrono::duration_cast<std::chrono::milliseconds>(now).count());
}

} // namespace carrom::server
