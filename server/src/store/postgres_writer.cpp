#include "store/postgres_writer.hpp"

#include "carrom/proto/journal_json.hpp"
#include "store/postgres_database.hpp"
#include "store/postgres_rating_writer.hpp"
#include "store/stored_json.hpp"

#include <pqxx/pqxx>

#include <stdexcept>

namespace carrom::store::postgres {
namespace {

// The prepared statements of the write connection, by name.
constexpr std::pair<const char*, const char*> kStatements[] = {
    {"insert_match", "INSERT INTO matches (id, room_code, rule_set, created_ms, physics_version, "
                     "rules_version, head) VALUES ($1, $2, $3, $4, $5, $6, $7)"},
    {"insert_player", "INSERT INTO players (name, match_id, created_ms) SELECT $1, id, "
                      "created_ms FROM matches WHERE id = $2 ON CONFLICT DO NOTHING"},
    {"insert_entry", "INSERT INTO entries (match_id, seq, time_ms, type, body) "
                     "VALUES ($1, $2, $3, $4, $5)"},
    {"finish_with_result", "UPDATE matches SET finished_ms = $1, result = $2 "
                           "WHERE id = $3 AND finished_ms IS NULL"},
    {"finish", "UPDATE matches SET finished_ms = $1 WHERE id = $2 AND finished_ms IS NULL"},
    {"upsert_token", "INSERT INTO seat_tokens (match_id, seat, token_sha256) "
                     "VALUES ($1, $2, decode($3, 'hex')) ON CONFLICT (match_id, seat) "
                     "DO UPDATE SET token_sha256 = excluded.token_sha256"},
    {"delete_token", "DELETE FROM seat_tokens WHERE match_id = $1 AND seat = $2"},
};

// Cluster mode's: a match created owned by this instance (epoch 0), and the ownership check that
// holds the match's row lock until the COMMIT (a takeover's claim waits for it, or it finds the
// epoch the claim incremented and updates nothing).
constexpr std::pair<const char*, const char*> kClusterStatements[] = {
    {"insert_owned_match",
     "INSERT INTO matches (id, room_code, rule_set, created_ms, physics_version, rules_version, "
     "head, owner_instance, owner_epoch) VALUES ($1, $2, $3, $4, $5, $6, $7, $8, 0)"},
    {"check_owner", "UPDATE matches SET owner_epoch = owner_epoch WHERE id = $1 AND "
                    "owner_instance = $2 AND owner_epoch = $3"},
};

// An error of the item, not of the database: it would fail every time (class 22, data
// exception: text the database cannot hold; class 23, integrity constraint violation).
bool item_error(const pqxx::sql_error& e) {
    const std::string& state = e.sqlstate();
    return state.size() == 5 && (state.substr(0, 2) == "22" || state.substr(0, 2) == "23");
}

// One item's refusal in the fast path: the transaction is spoilt; write again item by item.
struct RetryOneByOne {};

} // namespace

PostgresWriter::PostgresWriter(std::string url, std::string shown, bool lock)
    : url_(std::move(url)), shown_(std::move(shown)), lock_(lock) {}

PostgresWriter::PostgresWriter(std::string url, std::string shown, std::string instance_id,
                               std::shared_ptr<MatchOwnership> ownership)
    : url_(std::move(url)), shown_(std::move(shown)), lock_(false),
      instance_id_(std::move(instance_id)), ownership_(std::move(ownership)) {}

void PostgresWriter::prepare(pqxx::connection& c) const {
    for (const auto& [name, sql] : kStatements) {
        c.prepare(name, sql);
    }
    PostgresRatingWriter::prepare(c);
    if (ownership_) {
        for (const auto& [name, sql] : kClusterStatements) {
            c.prepare(name, sql);
        }
    }
}

PostgresWriter::~PostgresWriter() = default;

std::optional<StoreError> PostgresWriter::open() {
    try {
        connection_ = connect(url_);
    } catch (const std::exception& e) {
        return error_from(e, shown_, "connecting to");
    }
    if (auto e = prepare_database(*connection_, shown_)) {
        connection_.reset();
        return e;
    }
    try {
        if (lock_ && !try_lock(*connection_)) {
            connection_.reset();
            return StoreError{std::string(store_code::kLocked),
                              "cannot use " + shown_ +
                                  ": another carrom-server holds it (its advisory lock " +
                                  std::to_string(kLockKey) + ")"};
        }
        prepare(*connection_);
    } catch (const std::exception& e) {
        connection_.reset();
        return error_from(e, shown_, "opening");
    }
    return std::nullopt;
}

pqxx::connection& PostgresWriter::connection() {
    if (connection_ && connection_->is_open()) {
        return *connection_;
    }
    connection_.reset();
    auto c = connect(url_);
    if (lock_ && !try_lock(*c)) {
        throw std::runtime_error("another carrom-server holds " + shown_ +
                                 " (its advisory lock); writing waits for it to let go");
    }
    prepare(*c);
    connection_ = std::move(c);
    return *connection_;
}

std::vector<WriteRefusal> PostgresWriter::write(std::span<WriteItem> items,
                                                const std::function<bool()>& fail_before_commit) {
    try {
        try {
            return write_items(items, false, fail_before_commit);
        } catch (const RetryOneByOne&) {
            return write_items(items, true, fail_before_commit);
        }
    } catch (const pqxx::broken_connection&) {
        connection_.reset(); // made again at the next attempt
        throw;
    } catch (const pqxx::in_doubt_error&) {
        connection_.reset();
        throw;
    }
}

std::vector<WriteRefusal>
PostgresWriter::write_items(std::span<WriteItem> items, bool one_by_one,
                            const std::function<bool()>& fail_before_commit) {
    std::vector<WriteRefusal> refused;
    created_.clear();
    checked_.clear();
    finished_.clear();
    const auto refuse_lost = [&](std::size_t i) {
        refused.push_back(WriteRefusal{i, "the match is owned by another instance", true});
    };
    pqxx::work t(connection());
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!one_by_one) {
            try {
                if (!write_one(t, items[i])) {
                    refuse_lost(i);
                }
            } catch (const pqxx::sql_error& e) {
                if (!item_error(e)) {
                    throw;
                }
                throw RetryOneByOne{}; // t rolls back as it goes
            }
            continue;
        }
        std::optional<std::string> refusal;
        bool lost = false;
        const std::size_t finished_before = finished_.size();
        t.exec("SAVEPOINT item");
        try {
            lost = !write_one(t, items[i]);
        } catch (const pqxx::sql_error& e) {
            if (!item_error(e)) {
                throw;
            }
            const std::string what = e.what();
            refusal = what.substr(0, what.find('\n')); // one line
            t.exec("ROLLBACK TO SAVEPOINT item");
            // The rollback released the row locks the item's ownership check took: check again.
            checked_.clear();
            finished_.resize(finished_before);
            if (const auto* create = std::get_if<CreateItem>(&items[i].what)) {
                created_.erase(create->created.match_id);
            }
        }
        t.exec("RELEASE SAVEPOINT item");
        if (refusal) {
            refused.push_back(WriteRefusal{i, *refusal});
        } else if (lost) {
            refuse_lost(i);
        }
    }
    if (fail_before_commit && fail_before_commit()) {
        throw std::runtime_error("injected write failure (test seam)");
    }
    t.commit();
    if (ownership_) {
        for (auto& [match, owned] : created_) {
            ownership_->add(match, std::move(owned));
        }
        for (const MatchId& match : finished_) {
            ownership_->finished(match);
        }
        for (const auto& [match, owns] : checked_) {
            if (!owns) {
                ownership_->lost(match); // before the callers hear of the lost items
            }
        }
    }
    return refused;
}

bool PostgresWriter::owns(pqxx::transaction_base& t, const MatchId& match) {
    if (created_.count(match) != 0) {
        return true;
    }
    if (const auto it = checked_.find(match); it != checked_.end()) {
        return it->second;
    }
    const auto owned = ownership_->find(match);
    const bool owns =
        owned &&
        t.exec_prepared("check_owner", match, instance_id_, owned->epoch).affected_rows() == 1;
    checked_[match] = owns;
    return owns;
}

bool PostgresWriter::write_one(pqxx::transaction_base& t, const WriteItem& item) {
    return std::visit(
        [this, &t](const auto& what) {
            using T = std::decay_t<decltype(what)>;
            if constexpr (std::is_same_v<T, CreateItem>) {
                const proto::MatchCreated& c = what.created;
                if (ownership_) {
                    t.exec_prepared("insert_owned_match", c.match_id, c.room_code,
                                    std::string(rules::to_string(c.rule_set)),
                                    static_cast<std::int64_t>(c.time_ms), c.versions.physics,
                                    c.versions.rules, stored::head_text(c), instance_id_);
                    created_[c.match_id] = MatchOwnership::Owned{0, c.room_code};
                } else {
                    t.exec_prepared("insert_match", c.match_id, c.room_code,
                                    std::string(rules::to_string(c.rule_set)),
                                    static_cast<std::int64_t>(c.time_ms), c.versions.physics,
                                    c.versions.rules, stored::head_text(c));
                }
                for (const proto::JournalSeat& seat : c.seats) {
                    t.exec_prepared("insert_player", seat.name, c.match_id);
                }
                return true;
            } else if constexpr (std::is_same_v<T, PlayerItem>) {
                PostgresRatingWriter::save_player(t, what); // of no match
                return true;
            } else if (ownership_ && !owns(t, what.match)) {
                return false;
            } else if constexpr (std::is_same_v<T, AppendItem>) {
                t.exec_prepared("insert_entry", what.match, static_cast<std::int64_t>(what.seq),
                                static_cast<std::int64_t>(what.entry.time_ms),
                                std::string(proto::event_type(what.entry.event)),
                                stored::entry_text(what.entry));
                if (const auto* joined = std::get_if<proto::SeatJoinedEntry>(&what.entry.event)) {
                    t.exec_prepared("insert_player", joined->name, what.match);
                }
                const proto::OutcomeRecord* outcome = proto::outcome_of(what.entry.event);
                if (outcome != nullptr && outcome->game_end) {
                    t.exec_prepared(
                        "finish_with_result", static_cast<std::int64_t>(what.entry.time_ms),
                        stored::result_text(*outcome->game_end, outcome->scores), what.match);
                    PostgresRatingWriter::match_ended(t, what.match, *outcome->game_end,
                                                      what.entry.time_ms);
                    finished_.push_back(what.match);
                }
            } else if constexpr (std::is_same_v<T, SeatTokenItem>) {
                if (what.token) {
                    t.exec_prepared("upsert_token", what.match, what.seat, to_hex(*what.token));
                } else {
                    t.exec_prepared("delete_token", what.match, what.seat);
                }
            } else if constexpr (std::is_same_v<T, RatedSeatItem>) {
                PostgresRatingWriter::rated_seat(t, what);
            } else {
                t.exec_prepared("finish", static_cast<std::int64_t>(what.time_ms), what.match);
                finished_.push_back(what.match);
            }
            return true;
        },
        item.what);
}

} // namespace carrom::store::postgres
