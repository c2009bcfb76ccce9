#pragma once
// The card over the board while the connection is lost ("Reconnecting..." with the attempt and
// the time to the next try) or after the session gave up ("Disconnected", "Connection lost:
// <reason>"). The board stays visible, dimmed, around it. Drawn directly (its countdown changes
// every frame).

#include "carrom/client/reconnect_text.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "text.hpp"

#include <SFML/Graphics.hpp>

namespace carrom::client::app {

class ReconnectPanel {
public:
    // Draws the card centred on `board`; texts come from `texts` (wrapped to the card's width).
    void draw(sf::RenderTarget& target, TextCache& texts, const Rect& board,
              const ReconnectText& text) const;
};

} // namespace carrom::client::app
