#pragma once
// The lobby's "My matches": the player's last 20 matches (GET /players/NAME's "matches", newest
// first): opponent, result and date. A click on a row reads its journal and opens it as a replay
// (the replay window; the lobby comes back when it closes). Back (also Escape) returns to the
// lobby.

#include "list_page.hpp"
#include "server_records.hpp"

#include <SFML/Graphics.hpp>

#include <optional>
#include <string>
#include <vector>

namespace carrom::client::app {

class MatchListView {
public:
    struct Action {
        bool back = false;
        std::optional<std::size_t> open; // the match (index in the record's list) to replay
    };

    Action on_event(const sf::Event& event, const Rect& area,
                    const ServerRecords::Reading<PlayerRecord>& reading) const;
    // journal: the state of the replay asked for last (none asked: std::nullopt).
    ListPage page(const std::string& name, const ServerRecords::Reading<PlayerRecord>& reading,
                  const std::optional<ServerRecords::Reading<bool>>& journal) const;
    // Back, then one rect per match row shown.
    std::vector<Rect> control_rects(const Rect& area,
                                    const ServerRecords::Reading<PlayerRecord>& reading) const;
};

} // namespace carrom::client::app
