#pragma once
// The PostgreSQL store's read connection: journals, unfinished matches and match lists, decoded
// and checked (stored_json.hpp), and identified players and ratings (docs/ratings.md)
// (stored_json.hpp). Each read is one read-only REPEATABLE READ transaction (a consistent
// snapshot). Thread-safe: one mutex around the connection, which is made again after it breaks (the
// read that found it broken returns its error).

#include <pqxx/connection>
#include <pqxx/transaction_base>

#include "store/match_store.hpp"

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace carrom::store::postgres {

// A match's journal in transaction t (none when there is no such match); throws
// stored::BadJournal for one that does not decode.
std::optional<proto::MatchJournal> read_journal(pqxx::transaction_base& t, const MatchId& match);
// The seat token hashes of a match of `seats` seats, by seat.
std::vector<std::optional<TokenHash>> read_tokens(pqxx::transaction_base& t, const MatchId& match,
                                                  int seats);
// An unfinished match for recovery: its journal and tokens, or its error.
RecoveredMatch read_recovered(pqxx::transaction_base& t, const MatchId& match);

class PostgresReader {
public:
    // Connects. Throws (pqxx) when it cannot.
    PostgresReader(std::string url, std::string shown);
    ~PostgresReader();
    PostgresReader(const PostgresReader&) = delete;
    PostgresReader& operator=(const PostgresReader&) = delete;

    Loaded<std::vector<RecoveredMatch>> load_unfinished();
    Loaded<std::optional<proto::MatchJournal>> journal(const MatchId& match);
    Loaded<std::vector<MatchListing>> recent_matches(const std::string& player, int limit);
    Loaded<std::vector<IdentifiedPlayer>> load_players();
    Loaded<std::optional<IdentifiedPlayer>> find_player(const std::string& name_key);
    Loaded<std::vector<PlayerRating>> player_ratings(const PlayerKeyHash& player);
    Loaded<std::vector<LeaderboardRow>> leaderboard(rules::RuleSet rule_set, int limit);

private:
    // Runs f(transaction) in one read transaction and maps failures to a StoreError.
    template <class T, class F> Loaded<T> read(F f);

    std::mutex mutex_;
    std::string url_;
    std::string shown_;
    std::unique_ptr<pqxx::connection> connection_; // none after it broke, until the next read
};

} // namespace carrom::store::postgres
