#include "store_journal.hpp"

#include <chrono>

namespace carrom::server {

StoreJournal::StoreJournal(std::shared_ptr<store::MatchStore> store, RandomSource& random,
                           const std::atomic<bool>& stopping)
    : store_(std::move(store)), random_(random), stopping_(stopping) {}

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
