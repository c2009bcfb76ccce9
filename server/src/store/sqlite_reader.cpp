#include "store/sqlite_reader.hpp"

#include "store/sqlite_database.hpp"
#include "store/stored_json.hpp"

#include <SQLiteCpp/Statement.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace carrom::store::sqlite {
namespace {

using stored::bad;
using stored::BadJournal;

// Runs f in one read transaction (a consistent snapshot) and maps failures to a StoreError.
template <class T, class F> Loaded<T> read(SQLite::Database& db, const std::string& path, F f) {
    Loaded<T> out;
    try {
        db.exec("BEGIN");
        try {
            out.value = f();
        } catch (...) {
            db.exec("ROLLBACK");
            throw;
        }
        db.exec("COMMIT");
    } catch (const BadJournal& e) {
        out.error = StoreError{std::string(store_code::kBadJournal), e.what()};
    } catch (const SQLite::Exception& e) {
        out.error = error_from(e, path, "reading");
    }
    return out;
}

} // namespace

SqliteReader::SqliteReader(const std::string& path)
    : path_(path), db_(open_connection(path, true)) {}

std::optional<proto::MatchJournal> SqliteReader::read_journal(const MatchId& match) {
    SQLite::Statement head(db_, "SELECT head FROM matches WHERE id = ?");
    head.bind(1, match);
    if (!head.executeStep()) {
        return std::nullopt;
    }
    proto::MatchJournal journal;
    journal.created = stored::decode_head(match, head.getColumn(0).getString());
    SQLite::Statement entries(db_, "SELECT seq, body FROM entries WHERE match_id = ? ORDER BY seq");
    entries.bind(1, match);
    while (entries.executeStep()) {
        stored::add_entry(match, journal, entries.getColumn(0).getInt64(),
                          entries.getColumn(1).getString());
    }
    return journal;
}

std::vector<std::optional<TokenHash>> SqliteReader::read_tokens(const MatchId& match, int seats) {
    std::vector<std::optional<TokenHash>> out(static_cast<std::size_t>(seats));
    SQLite::Statement q(db_, "SELECT seat, token_sha256 FROM seat_tokens WHERE match_id = ?");
    q.bind(1, match);
    while (q.executeStep()) {
        const int seat = q.getColumn(0).getInt();
        const SQLite::Column blob = q.getColumn(1);
        TokenHash hash{};
        if (seat < 0 || seat >= seats || blob.getBytes() != static_cast<int>(hash.size())) {
            bad(match, "seat_tokens has a bad row for seat " + std::to_string(seat));
        }
        std::memcpy(hash.data(), blob.getBlob(), hash.size());
        out[static_cast<std::size_t>(seat)] = hash;
    }
    return out;
}

Loaded<std::vector<RecoveredMatch>> SqliteReader::load_unfinished() {
    const std::lock_guard lock(mutex_);
    return read<std::vector<RecoveredMatch>>(db_, path_, [this] {
        std::vector<std::pair<MatchId, bool>> ids; // id, rated
        SQLite::Statement q(db_, "SELECT m.id, EXISTS (SELECT 1 FROM rated_seats r "
                                 "WHERE r.match_id = m.id) FROM matches m "
                                 "WHERE m.finished_ms IS NULL ORDER BY m.created_ms, m.id");
        while (q.executeStep()) {
            ids.emplace_back(q.getColumn(0).getString(), q.getColumn(1).getInt() != 0);
        }
        std::vector<RecoveredMatch> out;
        for (const auto& [id, rated] : ids) {
            out.push_back(stored::recover(
                id, [&] { return read_journal(id); },
                [&](int seats) { return read_tokens(id, seats); }));
            out.back().rated = rated;
        }
        return out;
    });
}

Loaded<std::optional<proto::MatchJournal>> SqliteReader::journal(const MatchId& match) {
    const std::lock_guard lock(mutex_);
    return read<std::optional<proto::MatchJournal>>(db_, path_,
                                                    [&] { return read_journal(match); });
}

Loaded<std::vector<MatchListing>> SqliteReader::recent_matches(const std::string& player,
                                                               int limit) {
    const std::lock_guard lock(mutex_);
    return read<std::vector<MatchListing>>(db_, path_, [&] {
        SQLite::Statement q(db_, "SELECT m.id, m.room_code, m.head, m.created_ms, "
                                 "m.finished_ms, m.result FROM players p "
                                 "JOIN matches m ON m.id = p.match_id WHERE p.name = ? "
                                 "ORDER BY p.created_ms DESC, m.id DESC LIMIT ?");
        q.bind(1, player);
        q.bind(2, std::clamp(limit, 1, stored::kMaxListLimit));
        std::vector<MatchListing> out;
        while (q.executeStep()) {
            const auto column = [&q](int i) -> std::optional<std::string> {
                return q.isColumnNull(i) ? std::nullopt : std::optional(q.getColumn(i).getString());
            };
            out.push_back(stored::listing(
                q.getColumn(0).getString(), q.getColumn(1).getString(), q.getColumn(2).getString(),
                q.getColumn(3).getInt64(),
                q.isColumnNull(4) ? std::nullopt : std::optional(q.getColumn(4).getInt64()),
                column(5)));
        }
        return out;
    });
}

} // namespace carrom::store::sqlite
