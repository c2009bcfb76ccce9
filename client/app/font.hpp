#pragma once
// Finding a font at run time: $CARROM_FONT, then the usual DejaVu Sans locations.

#include <SFML/Graphics/Font.hpp>

#include <optional>
#include <string>
#include <vector>

namespace carrom::client::app {

std::vector<std::string> font_candidates();
// Loads the first candidate that exists; on failure `error` says what was tried and what to do.
bool load_font(sf::Font& font, std::string& error);

} // namespace carrom::client::app
