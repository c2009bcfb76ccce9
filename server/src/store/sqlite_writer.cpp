#include "store/sqlite_writer.hpp"

#include "carrom/proto/journal_json.hpp"
#include "store/sqlite_database.hpp"
#include "store/stored_json.hpp"

#include <sqlite3.h>

#include <optional>
#include <stdexcept>

namespace carrom::store::sqlite {
namespace {

// Runs a statement that returns no rows, then resets it for the next use (even when it throws).
void run(SQLite::Statement& statement) {
    struct Reset {
        SQLite::Statement& s;
        ~Reset() {
            s.tryReset(); // returns the last step's error, already thrown by exec()
            try {
                s.clearBindings(); // sqlite3_clear_bindings cannot fail
            } catch (...) {
            }
        }
    } reset{statement};
    statement.exec();
}

} // namespace

SqliteWriter::SqliteWriter(const std::string& path)
    : db_(open_connection(path, false)), begin_(db_, "BEGIN IMMEDIATE"), commit_(db_, "COMMIT"),
      savepoint_(db_, "SAVEPOINT item"), release_(db_, "RELEASE item"),
      rollback_to_(db_, "ROLLBACK TO item"),
      insert_match_(db_, "INSERT INTO matches (id, room_code, rule_set, created_ms, "
                         "physics_version, rules_version, head) VALUES (?, ?, ?, ?, ?, ?, ?)"),
      insert_player_(db_, "INSERT OR IGNORE INTO players (name, match_id, created_ms) "
                          "SELECT ?1, id, created_ms FROM matches WHERE id = ?2"),
      insert_entry_(db_, "INSERT INTO entries (match_id, seq, time_ms, type, body) "
                         "VALUES (?, ?, ?, ?, ?)"),
      finish_with_result_(db_, "UPDATE matches SET finished_ms = ?, result = ? "
                               "WHERE id = ? AND finished_ms IS NULL"),
      finish_(db_, "UPDATE matches SET finished_ms = ? WHERE id = ? AND finished_ms IS NULL"),
      upsert_token_(db_, "INSERT INTO seat_tokens (match_id, seat, token_sha256) VALUES (?, ?, ?) "
                         "ON CONFLICT (match_id, seat) DO UPDATE SET "
                         "token_sha256 = excluded.token_sha256"),
      delete_token_(db_, "DELETE FROM seat_tokens WHERE match_id = ? AND seat = ?"), ratings_(db_) {
    // Checkpoints are the checkpointer's (SqliteMatchStore): a commit never waits for one.
    db_.exec("PRAGMA wal_autocheckpoint = 0");
}

void SqliteWriter::rollback_if_open() {
    if (sqlite3_get_autocommit(db_.getHandle()) == 0) {
        sqlite3_exec(db_.getHandle(), "ROLLBACK", nullptr, nullptr, nullptr);
    }
}

std::vector<WriteRefusal> SqliteWriter::write(std::span<WriteItem> items,
                                              const std::function<bool()>& fail_before_commit) {
    std::vector<WriteRefusal> refused;
    try {
        run(begin_);
        for (std::size_t i = 0; i < items.size(); ++i) {
            run(savepoint_);
            std::optional<std::string> refusal;
            try {
                write_one(items[i]);
                run(release_);
            } catch (const SQLite::Exception& e) {
                if (e.getErrorCode() != SQLITE_CONSTRAINT) {
                    throw; // the file's problem: roll back, retry later
                }
                refusal = e.what(); // the item's problem: it would fail every time
            } catch (const nlohmann::json::exception& e) {
                refusal = e.what();
            }
            if (refusal) {
                run(rollback_to_);
                run(release_);
                refused.push_back(WriteRefusal{i, *refusal});
            }
        }
        if (fail_before_commit && fail_before_commit()) {
            throw std::runtime_error("injected write failure (test seam)");
        }
        run(commit_);
    } catch (...) {
        rollback_if_open();
        throw;
    }
    return refused;
}

void SqliteWriter::write_one(const WriteItem& item) {
    std::visit(
        [this](const auto& what) {
            using T = std::decay_t<decltype(what)>;
            if constexpr (std::is_same_v<T, CreateItem>) {
                create(what);
            } else if constexpr (std::is_same_v<T, AppendItem>) {
                append(what);
            } else if constexpr (std::is_same_v<T, SeatTokenItem>) {
                seat_token(what);
            } else if constexpr (std::is_same_v<T, PlayerItem>) {
                ratings_.save_player(what);
            } else if constexpr (std::is_same_v<T, RatedSeatItem>) {
                ratings_.rated_seat(what);
            } else {
                finish(what);
            }
        },
        item.what);
}

void SqliteWriter::create(const CreateItem& item) {
    const proto::MatchCreated& c = item.created;
    insert_match_.bind(1, c.match_id);
    insert_match_.bind(2, c.room_code);
    insert_match_.bind(3, std::string(rules::to_string(c.rule_set)));
    insert_match_.bind(4, static_cast<std::int64_t>(c.time_ms));
    insert_match_.bind(5, c.versions.physics);
    insert_match_.bind(6, c.versions.rules);
    insert_match_.bind(7, stored::head_text(c));
    run(insert_match_);
    for (const proto::JournalSeat& seat : c.seats) {
        insert_player_.bind(1, seat.name);
        insert_player_.bind(2, c.match_id);
        run(insert_player_);
    }
}

void SqliteWriter::append(const AppendItem& item) {
    insert_entry_.bind(1, item.match);
    insert_entry_.bind(2, static_cast<std::int64_t>(item.seq));
    insert_entry_.bind(3, static_cast<std::int64_t>(item.entry.time_ms));
    insert_entry_.bind(4, std::string(proto::event_type(item.entry.event)));
    insert_entry_.bind(5, stored::entry_text(item.entry));
    run(insert_entry_);
    if (const auto* joined = std::get_if<proto::SeatJoinedEntry>(&item.entry.event)) {
        insert_player_.bind(1, joined->name);
        insert_player_.bind(2, item.match);
        run(insert_player_);
    }
    const proto::OutcomeRecord* outcome = proto::outcome_of(item.entry.event);
    if (outcome != nullptr && outcome->game_end) {
        finish_with_result_.bind(1, static_cast<std::int64_t>(item.entry.time_ms));
        finish_with_result_.bind(2, stored::result_text(*outcome->game_end, outcome->scores));
        finish_with_result_.bind(3, item.match);
        run(finish_with_result_);
        ratings_.match_ended(item.match, *outcome->game_end, item.entry.time_ms);
    }
}

void SqliteWriter::seat_token(const SeatTokenItem& item) {
    if (item.token) {
        upsert_token_.bind(1, item.match);
        upsert_token_.bind(2, item.seat);
        upsert_token_.bind(3, item.token->data(), static_cast<int>(item.token->size()));
        run(upsert_token_);
    } else {
        delete_token_.bind(1, item.match);
        delete_token_.bind(2, item.seat);
        run(delete_token_);
    }
}

void SqliteWriter::finish(const FinishItem& item) {
    finish_.bind(1, static_cast<std::int64_t>(item.time_ms));
    finish_.bind(2, item.match);
    run(finish_);
}

} // namespace carrom::store::sqlite
