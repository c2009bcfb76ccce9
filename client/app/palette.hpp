#pragma once
// The colours that the client's panels share (the HUD, the lobby, the game-over and reconnect
// panels): one definition, so every view draws the same text, dimmed text, gold and buttons.

#include <SFML/Graphics/Color.hpp>

namespace carrom::client::app {

inline const sf::Color kText{242, 232, 214}; // text on the dark panels
inline const sf::Color kDim{186, 170, 150};  // secondary text
inline const sf::Color kGold{236, 184, 64};  // highlights: own seat, titles, button edges
inline const sf::Color kButton{96, 58, 28};  // a button's face

} // namespace carrom::client::app
