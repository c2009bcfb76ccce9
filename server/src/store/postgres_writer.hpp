#pragma once
// The PostgreSQL store's write connection: writes a batch of queued items in one transaction.
// Used by one thread only (the store's StoreWriteQueue writer). The connection is made again after
// it breaks (the database restarted, the network cut), and with it the advisory lock retaken: a
// writer that cannot retake it (another server took the database meanwhile) writes nothing.
//
// In cluster mode (an ownership given) there is no lock: every item of a match checks, in the
// transaction that writes it, that this instance still owns the match (matches.owner_instance and
// owner_epoch, docs/cluster.md). An item of a match another instance claimed is left out (a
// refusal marked lost) and the match reported lost after the COMMIT.

#include <pqxx/connection>
#include <pqxx/transaction_base>

#include "store/match_ownership.hpp"
#include "store/write_item.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace carrom::store::postgres {

class PostgresWriter {
public:
    // shown: the URL for messages (postgres_database.hpp, shown_url). lock: hold the
    // one-server advisory lock (single-instance mode).
    PostgresWriter(std::string url, std::string shown, bool lock);
    // Cluster mode: instance_id writes the matches ownership holds, and no others.
    PostgresWriter(std::string url, std::string shown, std::string instance_id,
                   std::shared_ptr<MatchOwnership> ownership);
    ~PostgresWriter();
    PostgresWriter(const PostgresWriter&) = delete;
    PostgresWriter& operator=(const PostgresWriter&) = delete;

    // Connects, validates and migrates the database and takes the lock; an error for the
    // operator (store_locked when another server holds the lock).
    std::optional<StoreError> open();

    // Writes the items in one transaction, each all or nothing. An item that would fail every
    // time (a constraint: an append to a match never created, a seq written twice; or text the
    // database cannot hold) is left out and listed; any other failure (the connection lost, the
    // lock not retaken, fail_before_commit returning true) rolls the whole transaction back and
    // throws.
    std::vector<WriteRefusal> write(std::span<WriteItem> items,
                                    const std::function<bool()>& fail_before_commit);

private:
    // A connection ready for writing: made (with the lock and prepared statements) if there is
    // none. Throws.
    pqxx::connection& connection();
    std::vector<WriteRefusal> write_items(std::span<WriteItem> items, bool one_by_one,
                                          const std::function<bool()>& fail_before_commit);
    // Writes one item; false (nothing written) when the match is not this instance's any more
    // (cluster mode).
    bool write_one(pqxx::transaction_base& t, const WriteItem& item);
    // Cluster mode: whether this instance owns the match in this transaction (checked once per
    // match and transaction, holding the match's row lock until the COMMIT).
    bool owns(pqxx::transaction_base& t, const MatchId& match);
    void prepare(pqxx::connection& c) const;

    std::string url_;
    std::string shown_;
    bool lock_ = true;
    std::string instance_id_;                   // cluster mode only
    std::shared_ptr<MatchOwnership> ownership_; // null: single-instance mode
    std::unique_ptr<pqxx::connection> connection_;
    // This transaction's matches: created (the epoch they get at COMMIT), checked, finished, lost.
    std::unordered_map<MatchId, MatchOwnership::Owned> created_;
    std::unordered_map<MatchId, bool> checked_;
    std::vector<MatchId> finished_;
};

} // namespace carrom::store::postgres
