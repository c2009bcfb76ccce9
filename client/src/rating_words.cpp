#include "carrom/client/rating_words.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {

namespace {

const RatingEntry* rating_for(const std::vector<RatingEntry>& ratings,
                              const std::string& rule_set) {
    const auto it = std::find_if(ratings.begin(), ratings.end(),
                                 [&](const RatingEntry& r) { return r.rule_set == rule_set; });
    return it == ratings.end() ? nullptr : &*it;
}

// The change shown after `now`, as rating_view.js words it: against the same rule set's rating
// in `before` when more games were played since; against 1500 for a rule set new since a read.
std::string change_suffix(const RatingEntry& now,
                          const std::optional<std::vector<RatingEntry>>& before) {
    if (!before) {
        return "";
    }
    if (const RatingEntry* old = rating_for(*before, now.rule_set)) {
        return now.games > old->games ? " " + rating_change_text(old->rating, now.rating) : "";
    }
    return now.games > 0 ? " " + rating_change_text(1500.0, now.rating) : "";
}

} // namespace

std::string rating_rule_set_word(const std::string& rule_set) {
    if (rule_set == "icf") {
        return "ICF";
    }
    if (rule_set == "seed") {
        return "classic";
    }
    if (rule_set == "discpool") {
        return "disc pool";
    }
    return rule_set; // "freestyle" and any newer one
}

std::string rating_change_text(double before, double after) {
    const long change = std::lround(after) - std::lround(before);
    return "(" + std::string(change >= 0 ? "+" : "") + std::to_string(change) + ")";
}

std::string rating_line(const std::optional<std::vector<RatingEntry>>& before,
                        const std::vector<RatingEntry>& after) {
    std::string line;
    for (const RatingEntry& r : after) {
        line += line.empty() ? "Rating: " : ", ";
        line += rating_rule_set_word(r.rule_set) + " " + r.label + change_suffix(r, before);
    }
    return line;
}

std::string seat_rating_text(const std::string& rule_set, const std::vector<RatingEntry>& after,
                             const std::optional<std::vector<RatingEntry>>& before) {
    const RatingEntry* now = rating_for(after, rule_set);
    return now == nullptr ? "" : now->label + change_suffix(*now, before);
}

} // namespace carrom::client
