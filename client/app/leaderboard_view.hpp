#pragma once
// The lobby's leaderboard: rank, name, rating and games of the established players of one rule
// set (GET /leaderboard, best first, at most 20 shown). Its buttons: the rule set (each press
// steps to the next and reads again; also Tab) and Back (also Escape).

#include "list_page.hpp"
#include "server_records.hpp"

#include "carrom/proto/types.hpp"

#include <SFML/Graphics.hpp>

#include <vector>

namespace carrom::client::app {

class LeaderboardView {
public:
    enum class Action { None, Back, Read };

    // Read: the rule set changed, read the leaderboard again.
    Action on_event(const sf::Event& event, const Rect& area);
    void set_rule_set(proto::RuleSet rule_set) { rule_set_ = rule_set; }
    proto::RuleSet rule_set() const { return rule_set_; }
    ListPage page(const ServerRecords::Reading<Leaderboard>& reading) const;
    // The buttons' rects: the rule set, Back.
    std::vector<Rect> control_rects(const Rect& area) const;

private:
    proto::RuleSet rule_set_ = proto::RuleSet::Icf;
};

} // namespace carrom::client::app
