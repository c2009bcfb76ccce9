#pragma once
// The in-window lobby: singles or doubles, then create a room (alone or with server bots in the
// other seats), quick match, or type a room code to join as a player or to watch. Also shows the
// connection status and the last error.

#include "carrom/client/client_session.hpp"
#include "carrom/client/screen_mapping.hpp"

#include <SFML/Graphics.hpp>

#include <optional>
#include <string>

namespace carrom::client::app {

class LobbyView {
public:
    explicit LobbyView(const sf::Font& font) : font_(font) {}

    // A button press or Enter in the code field gives a room request.
    std::optional<RoomRequest> on_event(const sf::Event& event, const Rect& area);
    void draw(sf::RenderTarget& target, const Rect& area, const std::string& name,
              const std::string& status, const std::string& error, bool can_choose) const;

private:
    enum Control { kSingles, kDoubles, kCreate, kBot, kQuick, kCode, kJoin, kWatch, kControlCount };
    Rect control_rect(Control c, const Rect& area) const;
    std::optional<RoomRequest> press(Control c);

    const sf::Font& font_;
    std::string code_;
    int seats_ = 2; // 2: singles, 4: doubles (for create, the bots and quick match)
};

} // namespace carrom::client::app
