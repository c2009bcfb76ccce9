#pragma once
// The store's write connection: writes a batch of queued items in one transaction. Used by one
// thread only (SqliteMatchStore's writer).

#include "store/sqlite_rating_writer.hpp"
#include "store/write_item.hpp"

#include <SQLiteCpp/Database.h>
#include <SQLiteCpp/Statement.h>

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace carrom::store::sqlite {

class SqliteWriter {
public:
    // Opens the connection to a prepared database (sqlite_database.hpp). Throws SQLite::Exception.
    explicit SqliteWriter(const std::string& path);

    // Writes the items in one transaction, each all or nothing. An item that would fail every
    // time (a constraint: an append to a match never created, a seq written twice; or text that
    // cannot be encoded) is left out and listed; any other failure (disk full, I/O error,
    // fail_before_commit returning true) rolls the whole transaction back and throws
    // (SQLite::Exception or std::runtime_error).
    std::vector<WriteRefusal> write(std::span<WriteItem> items,
                                    const std::function<bool()>& fail_before_commit);

private:
    void write_one(const WriteItem& item);
    void create(const CreateItem& item);
    void append(const AppendItem& item);
    void seat_token(const SeatTokenItem& item);
    void finish(const FinishItem& item);
    void rollback_if_open();

    SQLite::Database db_;
    SQLite::Statement begin_;
    SQLite::Statement commit_;
    SQLite::Statement savepoint_;
    SQLite::Statement release_;
    SQLite::Statement rollback_to_;
    SQLite::Statement insert_match_;
    SQLite::Statement insert_player_;
    SQLite::Statement insert_entry_;
    SQLite::Statement finish_with_result_;
    SQLite::Statement finish_;
    SQLite::Statement upsert_token_;
    SQLite::Statement delete_token_;
    SqliteRatingWriter ratings_; // identities and ratings, in the same transactions
};

} // namespace carrom::store::sqlite
