#include "carrom/client/rating_book.hpp"

#include "carrom/client/rating_words.hpp"

#include <algorithm>
#include <cctype>
#include <ctime>

namespace carrom::client {

namespace {

bool same_name(const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

const RatingEntry* book_rating_for(const std::vector<RatingEntry>& ratings,
                                   const std::string& rule_set) {
    for (const RatingEntry& r : ratings) {
        if (r.rule_set == rule_set) {
            return &r;
        }
    }
    return nullptr;
}

// "2026-11-28 17:40 UTC" for Unix ms.
std::string utc_minute(std::int64_t ms) {
    const std::time_t seconds = static_cast<std::time_t>(ms / 1000);
    std::tm parts{};
    if (gmtime_r(&seconds, &parts) == nullptr) {
        return "";
    }
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &parts);
    return text;
}

} // namespace

void RatingBook::record(const PlayerRecord& record, bool as_base) {
    latest_[record.name] = record.ratings;
    if (as_base) {
        base_[record.name] = record.ratings;
    }
}

void RatingBook::game_starts(const std::vector<std::string>& names) {
    for (const std::string& name : names) {
        if (const auto it = latest_.find(name); it != latest_.end()) {
            base_[name] = it->second;
        }
    }
}

std::string RatingBook::lobby_line(const std::string& name) const {
    const auto it = latest_.find(name);
    if (it == latest_.end()) {
        return "";
    }
    const auto base = base_.find(name);
    return rating_line(base == base_.end() ? std::nullopt : std::optional(base->second),
                       it->second);
}

std::string RatingBook::seat_text(const std::string& name, const std::string& rule_set) const {
    const auto it = latest_.find(name);
    if (it == latest_.end()) {
        return "";
    }
    const auto base = base_.find(name);
    return seat_rating_text(rule_set, it->second,
                            base == base_.end() ? std::nullopt : std::optional(base->second));
}

bool RatingBook::changed(const std::string& name, const std::string& rule_set) const {
    const auto it = latest_.find(name);
    const auto base = base_.find(name);
    if (it == latest_.end() || base == base_.end()) {
        return false;
    }
    const RatingEntry* now = book_rating_for(it->second, rule_set);
    const RatingEntry* old = book_rating_for(base->second, rule_set);
    return now != nullptr && now->games > (old == nullptr ? 0 : old->games);
}

MatchLine match_line(const MatchEntry& match, const std::string& me) {
    MatchLine line;
    int my_team = -1;
    std::vector<std::string> others;
    for (std::size_t i = 0; i < match.players.size(); ++i) {
        if (my_team < 0 && same_name(match.players[i], me)) {
            my_team = i < match.teams.size() ? match.teams[i] : static_cast<int>(i);
        } else {
            others.push_back(match.players[i]);
        }
    }
    for (std::size_t i = 0; i < others.size(); ++i) {
        line.opponent += (i == 0 ? "" : i + 1 == others.size() ? " & " : ", ") + others[i];
    }
    // Scores are per team: ours first (web: my_matches.js, the same words).
    std::string score;
    if (match.scores.size() == 2 && (my_team == 0 || my_team == 1)) {
        score = " " + std::to_string(match.scores[static_cast<std::size_t>(my_team)]) + " : " +
                std::to_string(match.scores[static_cast<std::size_t>(1 - my_team)]);
    }
    if (match.reason.empty()) {
        line.result = match.finished_ms == 0 ? "playing" : "unfinished";
    } else if (!match.winner_team) {
        line.result = "drawn" + score;
    } else {
        line.result = (*match.winner_team == my_team ? "won" : "lost") + score;
    }
    line.date = utc_minute(match.finished_ms > 0 ? match.finished_ms : match.created_ms);
    return line;
}

} // namespace carrom::client
