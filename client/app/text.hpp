#pragma once
// Text and panels for the HUD and the lobby.

#include "carrom/client/screen_mapping.hpp"

#include <SFML/Graphics.hpp>

#include <string>

namespace carrom::client::app {

enum class Align { Left, Centre, Right };

// Draws text with its left/centre/right edge at x and its vertical middle at y_mid. Returns its
// width in window px.
float draw_text(sf::RenderTarget& target, const sf::Font& font, const std::string& text,
                unsigned size, float x, float y_mid, sf::Color colour, Align align = Align::Left);
void draw_panel(sf::RenderTarget& target, const Rect& rect, sf::Color fill,
                sf::Color outline = sf::Color::Transparent, float outline_px = 0.0f);

} // namespace carrom::client::app
