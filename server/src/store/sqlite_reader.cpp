#include "store/sqlite_reader.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/match_json.hpp"
#include "store/sqlite_database.hpp"

#include <SQLiteCpp/Statement.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace carrom::store::sqlite {
namespace {

using Json = nlohmann::json;

constexpr int kMaxListLimit = 100;

// A stored value that does not decode: the message names the match and where.
struct BadJournal : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] void bad(const MatchId& match, const std::string& what) {
    throw BadJournal("the stored journal of match " + match + " is damaged: " + what);
}

Json parse_stored(const MatchId& match, const std::string& text, std::string_view what) {
    auto parsed = proto::parse_json_text(text, proto::kMaxJournalBytes);
    if (!parsed.ok()) {
        bad(match, std::string(what) + ": " + parsed.error->message);
    }
    return std::move(parsed.value);
}

proto::MatchCreated decode_head(const MatchId& match, const std::string& text) {
    auto head = proto::decode_match_created(parse_stored(match, text, "match"));
    if (!head.ok()) {
        bad(match, head.error->path + ": " + head.error->message);
    }
    return std::move(head.value);
}

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
    journal.created = decode_head(match, head.getColumn(0).getString());
    SQLite::Statement entries(db_, "SELECT seq, body FROM entries WHERE match_id = ? ORDER BY seq");
    entries.bind(1, match);
    while (entries.executeStep()) {
        const std::int64_t seq = entries.getColumn(0).getInt64();
        const auto expected = static_cast<std::int64_t>(journal.entries.size());
        if (seq != expected) {
            bad(match, "entry " + std::to_string(expected) + " is missing");
        }
        const std::string at = "entries[" + std::to_string(seq) + "]";
        auto entry = proto::decode_journal_entry(
            parse_stored(match, entries.getColumn(1).getString(), at), journal.created, at);
        if (!entry.ok()) {
            bad(match, entry.error->path + ": " + entry.error->message);
        }
        journal.entries.push_back(std::move(entry.value));
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
        std::vector<MatchId> ids;
        SQLite::Statement q(db_, "SELECT id FROM matches WHERE finished_ms IS NULL "
                                 "ORDER BY created_ms, id");
        while (q.executeStep()) {
            ids.push_back(q.getColumn(0).getString());
        }
        std::vector<RecoveredMatch> out;
        for (const MatchId& id : ids) {
            RecoveredMatch match;
            match.id = id;
            try {
                match.journal = read_journal(id);
                if (!match.journal) {
                    bad(id, "it has no head");
                }
                match.seat_tokens = read_tokens(id, match.journal->created.rules.seat_count);
            } catch (const BadJournal& e) { // this match only; the others recover
                match.journal.reset();
                match.error = StoreError{std::string(store_code::kBadJournal), e.what()};
            }
            out.push_back(std::move(match));
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
        q.bind(2, std::clamp(limit, 1, kMaxListLimit));
        std::vector<MatchListing> out;
        while (q.executeStep()) {
            MatchListing m;
            m.id = q.getColumn(0).getString();
            m.room_code = q.getColumn(1).getString();
            const proto::MatchCreated head = decode_head(m.id, q.getColumn(2).getString());
            m.rule_set = head.rule_set;
            for (const proto::JournalSeat& seat : head.seats) {
                m.teams.push_back(
                    rules::team_of_seat(static_cast<int>(m.players.size()), head.rules.seat_count));
                m.players.push_back(seat.name);
            }
            m.created_ms = q.getColumn(3).getInt64();
            if (!q.isColumnNull(4)) {
                m.finished_ms = q.getColumn(4).getInt64();
            }
            if (!q.isColumnNull(5)) {
                const Json r = parse_stored(m.id, q.getColumn(5).getString(), "result");
                const int teams = rules::team_count(head.rules.seat_count);
                if (!r.is_object() || !r.contains("result") || !r.contains("scores")) {
                    bad(m.id, "its stored result does not decode");
                }
                auto result = proto::decode_game_result(r["result"], teams, "result");
                const Json& scores = r["scores"];
                if (!result.ok() || !scores.is_array() ||
                    scores.size() != static_cast<std::size_t>(teams) ||
                    !std::all_of(scores.begin(), scores.end(),
                                 [](const Json& s) { return s.is_number_integer(); })) {
                    bad(m.id, "its stored result does not decode");
                }
                m.result = result.value;
                for (const Json& s : scores) {
                    m.scores.push_back(s.get<int>());
                }
            }
            out.push_back(std::move(m));
        }
        return out;
    });
}

} // namespace carrom::store::sqlite
