#include "store/postgres_reader.hpp"

#include "store/postgres_database.hpp"
#include "store/postgres_rating_row.hpp"
#include "store/stored_json.hpp"

#include <pqxx/pqxx>

#include <algorithm>
#include <cstring>

namespace carrom::store::postgres {
namespace {

using ReadTransaction = pqxx::transaction<pqxx::repeatable_read, pqxx::read_only>;

// The columns key_sha256, name, name_key, created_ms.
IdentifiedPlayer player_fields(const pqxx::row& row) {
    return IdentifiedPlayer{key_hash_field(row[0]), row[1].as<std::string>(),
                            row[2].as<std::string>(), row[3].as<std::int64_t>()};
}

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
    RecoveredMatch out = stored::recover(
        match, [&] { return read_journal(t, match); },
        [&](int seats) { return read_tokens(t, match, seats); });
    out.rated =
        t.exec_params("SELECT EXISTS (SELECT 1 FROM rated_seats WHERE match_id = $1)", match)[0][0]
            .as<bool>();
    return out;
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

Loaded<std::vector<IdentifiedPlayer>> PostgresReader::load_players() {
    return read<std::vector<IdentifiedPlayer>>([](pqxx::transaction_base& t) {
        std::vector<IdentifiedPlayer> out;
        for (const auto& row : t.exec("SELECT key_sha256, name, name_key, created_ms "
                                      "FROM identities")) {
            out.push_back(player_fields(row));
        }
        return out;
    });
}

Loaded<std::optional<IdentifiedPlayer>> PostgresReader::find_player(const std::string& name_key) {
    return read<std::optional<IdentifiedPlayer>>([&](pqxx::transaction_base& t) {
        std::optional<IdentifiedPlayer> out;
        const pqxx::result r = t.exec_params("SELECT key_sha256, name, name_key, created_ms "
                                             "FROM identities WHERE name_key = $1",
                                             name_key);
        if (!r.empty()) {
            out = player_fields(r[0]);
        }
        return out;
    });
}

Loaded<std::vector<PlayerRating>> PostgresReader::player_ratings(const PlayerKeyHash& player) {
    return read<std::vector<PlayerRating>>([&](pqxx::transaction_base& t) {
        std::vector<PlayerRating> out;
        for (const auto& row : t.exec_params(
                 "SELECT rule_set, rating, deviation, volatility, games, wins, losses, draws, "
                 "last_game_ms FROM ratings WHERE key_sha256 = decode($1, 'hex') "
                 "ORDER BY rule_set COLLATE \"C\"",
                 to_hex(player))) {
            rules::RuleSet rule_set = rules::RuleSet::Icf;
            if (rules::parse_rule_set(row[0].as<std::string>(), rule_set)) {
                out.push_back(rating_fields(row, 1, rule_set));
            }
        }
        return out;
    });
}

Loaded<std::vector<LeaderboardRow>> PostgresReader::leaderboard(rules::RuleSet rule_set,
                                                                int limit) {
    return read<std::vector<LeaderboardRow>>([&](pqxx::transaction_base& t) {
        std::vector<LeaderboardRow> out;
        // name_key in byte order (COLLATE "C"), as SQLite compares text.
        for (const auto& row : t.exec_params(
                 "SELECT i.name, r.rating, r.deviation, r.volatility, r.games, r.wins, r.losses, "
                 "r.draws, r.last_game_ms FROM ratings r JOIN identities i USING (key_sha256) "
                 "WHERE r.rule_set = $1 AND r.deviation < $2 "
                 "ORDER BY r.rating DESC, r.games DESC, i.name_key COLLATE \"C\" LIMIT $3",
                 std::string(rules::to_string(rule_set)), ratings::kProvisionalDeviation,
                 std::clamp(limit, 1, kMaxLeaderboardRows))) {
            out.push_back(
                LeaderboardRow{row[0].as<std::string>(), rating_fields(row, 1, rule_set)});
        }
        return out;
    });
}

} // namespace carrom::store::postgres
