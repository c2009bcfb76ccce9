#include "store/postgres_reader.hpp"

#include "store/postgres_database.hpp"
#include "store/stored_json.hpp"

#include <pqxx/pqxx>

#include <algorithm>
#include <cstring>

namespace carrom::store::postgres {
namespace {

using ReadTransaction = pqxx::transaction<pqxx::repeatable_read, pqxx::read_only>;

} // namespace

std::optional<proto::MatchJournal> read_journal(pqxx::transaction_base& t, const MatchId& match) {
    const pqxx::result head = t.exec_params("SELECT head FROM matches WHERE id = $1", match);
    if (head.empty()) {
        return std::nullopt;
    }
    proto::MatchJournal journal;
    journal.created = stored::decode_head(match, head[0][0].as<std::string>());
    for (const auto& row :
         t.exec_params("SELECT seq, body FROM entries WHERE match_id = $1 ORDER BY seq", match)) {
        stored::add_entry(match, journal, row[0].as<std::int64_t>(), row[1].as<std::string>());
    }
    return journal;
}

std::vector<std::optional<TokenHash>> read_tokens(pqxx::transaction_base& t, const MatchId& match,
                                                  int seats) {
    std::vector<std::optional<TokenHash>> out(static_cast<std::size_t>(seats));
    for (const auto& row :
         t.exec_params("SELECT seat, token_sha256 FROM seat_tokens WHERE match_id = $1", match)) {
        const int seat = row[0].as<int>();
        const pqxx::binarystring blob(row[1]);
        TokenHash hash{};
        if (seat < 0 || seat >= seats || blob.size() != hash.size()) {
            stored::bad(match, "seat_tokens has a bad row for seat " + std::to_string(seat));
        }
        std::memcpy(hash.data(), blob.data(), hash.size());
        out[static_cast<std::size_t>(seat)] = hash;
    }
    return out;
}

RecoveredMatch read_recovered(pqxx::transaction_base& t, const MatchId& match) {
    return stored::recover(
        match, [&] { return read_journal(t, match); },
        [&](int seats) { return read_tokens(t, match, seats); });
}

PostgresReader::PostgresReader(std::string url, std::string shown)
    : url_(std::move(url)), shown_(std::move(shown)), connection_(connect(url_)) {}

PostgresReader::~PostgresReader() = default;

template <class T, class F> Loaded<T> PostgresReader::read(F f) {
    const std::lock_guard lock(mutex_);
    Loaded<T> out;
    try {
        if (!connection_ || !connection_->is_open()) {
            connection_ = connect(url_);
        }
        ReadTransaction t(*connection_);
        out.value = f(t);
        t.commit();
    } catch (const stored::BadJournal& e) {
        out.error = StoreError{std::string(store_code::kBadJournal), e.what()};
    } catch (const pqxx::broken_connection& e) {
        connection_.reset(); // made again at the next read
        out.error = error_from(e, shown_, "reading");
    } catch (const std::exception& e) {
        out.error = error_from(e, shown_, "reading");
    }
    return out;
}

Loaded<std::vector<RecoveredMatch>> PostgresReader::load_unfinished() {
    return read<std::vector<RecoveredMatch>>([](pqxx::transaction_base& t) {
        std::vector<RecoveredMatch> out;
        for (const auto& row : t.exec("SELECT id FROM matches WHERE finished_ms IS NULL "
                                      "ORDER BY created_ms, id")) {
            out.push_back(read_recovered(t, row[0].as<std::string>()));
        }
        return out;
    });
}

Loaded<std::optional<proto::MatchJournal>> PostgresReader::journal(const MatchId& match) {
    return read<std::optional<proto::MatchJournal>>(
        [&](pqxx::transaction_base& t) { return read_journal(t, match); });
}

Loaded<std::vector<MatchListing>> PostgresReader::recent_matches(const std::string& player,
                                                                 int limit) {
    return read<std::vector<MatchListing>>([&](pqxx::transaction_base& t) {
        std::vector<MatchListing> out;
        for (const auto& row : t.exec_params(
                 "SELECT m.id, m.room_code, m.head, m.created_ms, m.finished_ms, m.result "
                 "FROM players p JOIN matches m ON m.id = p.match_id WHERE p.name = $1 "
                 "ORDER BY p.created_ms DESC, m.id DESC LIMIT $2",
                 player, std::clamp(limit, 1, stored::kMaxListLimit))) {
            out.push_back(stored::listing(
                row[0].as<std::string>(), row[1].as<std::string>(), row[2].as<std::string>(),
                row[3].as<std::int64_t>(),
                row[4].is_null() ? std::nullopt : std::optional(row[4].as<std::int64_t>()),
                row[5].is_null() ? std::nullopt : std::optional(row[5].as<std::string>())));
        }
        return out;
    });
}

} // namespace carrom::store::postgres
