#include "server_records.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/types.hpp"

#include <utility>

namespace carrom::client::app {

namespace {

// The requests' keys: "player:WHY:NAME" (WHY: "base" for a read as a game begins, "late"
// otherwise), "leaderboard", "matches:NAME", "journal".
constexpr std::string_view kPlayerKey = "player:";

std::vector<std::string> seat_names(const MatchView& view) {
    std::vector<std::string> names;
    for (const SeatView& s : view.seats) {
        if (s.occupied && !s.bot && !s.name.empty()) {
            names.push_back(s.name);
        }
    }
    return names;
}

} // namespace

void ServerRecords::read_player(const std::string& name, const std::string& why) {
    const std::string key = std::string(kPlayerKey) + why + ":" + name;
    if (!api_.running(key)) {
        api_.get(key, player_path(name));
    }
}

void ServerRecords::lobby_entered(const std::string& name, double now) {
    lobby_name_ = name;
    read_player(name, "late");
    lobby_reread_at_ = now + 1.5;
}

void ServerRecords::room_seen(const MatchView& view, double now) {
    const std::vector<std::string> names = seat_names(view);
    seat_players_.resize(view.seats.size());
    for (std::size_t i = 0; i < view.seats.size(); ++i) {
        const SeatView& s = view.seats[i];
        if (s.occupied && !s.bot && !s.name.empty()) {
            seat_players_[i] = s.name;
        }
    }
    const bool over = view.phase == proto::Phase::GameOver;
    for (const std::string& name : names) {
        if (room_names_read_.insert(name).second) {
            read_player(name, over ? "late" : "base");
        }
    }
    if (over && !game_over_seen_) {
        game_over_seen_ = true;
        seats_reread_at_ = now + 1.0;
        game_names_.clear(); // who played, also a player who left as the game ended
        for (const std::string& name : seat_players_) {
            if (!name.empty()) {
                game_names_.push_back(name);
            }
        }
    } else if (!over && game_over_seen_ && view.phase != proto::Phase::Waiting) {
        game_over_seen_ = false; // a rematch began: its change shows against the ratings now
        book_.game_starts(names);
    }
}

void ServerRecords::room_left() {
    room_names_read_.clear();
    seat_players_.clear();
    game_over_seen_ = false;
    seats_reread_at_ = -1.0;
}

void ServerRecords::read_leaderboard(proto::RuleSet rule_set) {
    leaderboard_ = std::monostate{};
    leaderboard_rule_set_ = std::string(proto::to_string(rule_set));
    if (!api_.get("leaderboard", "/leaderboard?rule_set=" +
                                     std::string(proto::to_string(rule_set)) + "&limit=50")) {
        leaderboard_ = std::string("No server to ask (or too many reads at once).");
    }
}

void ServerRecords::read_matches(const std::string& name) {
    matches_ = std::monostate{};
    matches_name_ = name;
    if (!api_.get("matches:" + name, player_path(name))) {
        matches_ = std::string("No server to ask (or too many reads at once).");
    }
}

void ServerRecords::read_journal(const std::string& path) {
    journal_state_ = std::monostate{};
    if (!api_.get("journal", path, proto::kMaxJournalBytes)) {
        journal_state_ = std::string("No server to ask (or too many reads at once).");
    }
}

void ServerRecords::update(double now) {
    if (lobby_reread_at_ >= 0.0 && now >= lobby_reread_at_) {
        lobby_reread_at_ = -1.0;
        read_player(lobby_name_, "late");
    }
    if (seats_reread_at_ >= 0.0 && now >= seats_reread_at_) {
        seats_reread_at_ = -1.0;
        for (const std::string& name : game_names_) {
            read_player(name, "late");
        }
    }
    now_ = now;
    for (auto it = retries_.begin(); it != retries_.end();) {
        if (now >= std::get<0>(*it)) {
            read_player(std::get<1>(*it), std::get<2>(*it));
            it = retries_.erase(it);
        } else {
            ++it;
        }
    }
    for (const ApiFetcher::Done& done : api_.take_done()) {
        take(done);
    }
}

void ServerRecords::take(const ApiFetcher::Done& done) {
    const std::string& key = done.key;
    if (key.rfind(kPlayerKey, 0) == 0) {
        const std::size_t colon = key.find(':', kPlayerKey.size());
        const std::string name = key.substr(colon + 1);
        const std::string why = key.substr(kPlayerKey.size(), colon - kPlayerKey.size());
        auto parsed = parse_player_answer(name, done.answer);
        if (auto* record = std::get_if<PlayerRecord>(&parsed)) {
            record->name = name; // as the room spells it (the server's may differ in case)
            book_.record(*record, why.rfind("base", 0) == 0);
        } else if ((why == "base" || why == "late") && !keeps_no_players(done.answer)) {
            // A busy store (503), the rate limit (429) or no answer: once more in 1 s (a server
            // that keeps no players, 503 store_disabled, is not asked again). Until then the
            // seat or the lobby line stays as it was.
            retries_.emplace_back(retry_at(), name, why + "-again");
        }
        return;
    }
    if (key == "leaderboard") {
        auto parsed = parse_leaderboard_answer(done.answer);
        if (auto* board = std::get_if<Leaderboard>(&parsed)) {
            if (board->rule_set != leaderboard_rule_set_) {
                return; // an earlier choice's answer, come late
            }
            leaderboard_ = std::move(*board);
        } else {
            leaderboard_ = std::get<std::string>(std::move(parsed));
        }
    } else if (key == "matches:" + matches_name_) {
        auto parsed = parse_player_answer(matches_name_, done.answer);
        if (auto* record = std::get_if<PlayerRecord>(&parsed)) {
            matches_ = std::move(*record);
        } else {
            matches_ = std::get<std::string>(std::move(parsed));
        }
    } else if (key == "journal") {
        if (auto problem = answer_problem(done.answer)) {
            journal_state_ = std::move(*problem);
            return;
        }
        auto loaded = ReplayModel::load_text(done.answer.body);
        if (auto* error = std::get_if<proto::Error>(&loaded)) {
            journal_state_ = "The match's journal cannot be replayed: " + error->message;
            return;
        }
        journal_state_ = true;
        journal_ = std::get<ReplayModel>(std::move(loaded));
    }
}

} // namespace carrom::client::app
