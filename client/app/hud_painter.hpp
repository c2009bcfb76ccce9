#pragma once
// The HUD: seats with names, colours, scores and dues along the top; whose turn, the shot clock
// and the queen in the middle; room, rule set, connection and round trip along the bottom;
// recent messages over the board; the room code large while the room waits for a player.

#include "carrom/client/match_model.hpp"
#include "carrom/client/screen_mapping.hpp"

#include <SFML/Graphics.hpp>

#include <optional>
#include <string>

namespace carrom::client::app {

struct ConnectionLine {
    std::string text;               // "Connected", "Reconnecting (attempt 2)..."
    bool healthy = true;
    std::optional<double> rtt_ms;
};

class HudPainter {
public:
    explicit HudPainter(const sf::Font& font) : font_(font) {}
    void draw(sf::RenderTarget& target, const ScreenLayout& layout, const MatchModel& model,
              const ConnectionLine& connection, double local_s) const;

private:
    void draw_seat(sf::RenderTarget& target, const Rect& area, const MatchModel& model, int seat,
                   bool right) const;
    void draw_centre(sf::RenderTarget& target, const Rect& area, const MatchModel& model,
                     double local_s) const;
    void draw_bottom(sf::RenderTarget& target, const Rect& area, const MatchModel& model,
                     const ConnectionLine& connection) const;
    void draw_messages(sf::RenderTarget& target, const Rect& board, const MatchModel& model,
                       double local_s) const;
    void draw_room_code(sf::RenderTarget& target, const Rect& board,
                        const MatchModel& model) const;

    const sf::Font& font_;
};

} // namespace carrom::client::app
