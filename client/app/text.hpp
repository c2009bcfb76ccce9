#pragma once
// Text and panels for the HUD and the lobby.

#include "carrom/client/screen_mapping.hpp"

#include <SFML/Graphics.hpp>

#include <map>
#include <string>
#include <utility>

namespace carrom::client::app {

enum class Align { Left, Centre, Right };

// Draws text with its left/centre/right edge at x and its vertical middle at y_mid. Returns its
// width in window px. Lays the glyphs out on every call: for screens drawn once (lobby, panels).
float draw_text(sf::RenderTarget& target, const sf::Font& font, const std::string& text,
                unsigned size, float x, float y_mid, sf::Color colour, Align align = Align::Left);
void draw_panel(sf::RenderTarget& target, const Rect& rect, sf::Color fill,
                sf::Color outline = sf::Color::Transparent, float outline_px = 0.0f);

struct FittedText {
    std::string text; // UTF-8, maybe shortened with "..."
    unsigned size = 0;
};

// Texts laid out once per (string, size) and reused from frame to frame; moving or recolouring
// a laid-out text costs nothing. Holds at most kMaxEntries texts (then starts over).
class TextCache {
public:
    explicit TextCache(const sf::Font& font) : font_(font) {}
    // As draw_text.
    float draw(sf::RenderTarget& target, const std::string& text, unsigned size, float x,
               float y_mid, sf::Color colour, Align align = Align::Left);
    // Width of the text in window px.
    float width(const std::string& text, unsigned size);
    // The text at the largest size from `size` down to `min_size` whose width is at most `width`
    // px; still too wide at min_size, it loses characters at its end for "..." until it fits.
    // Measures without filling the cache (a caller keeps the result).
    FittedText fit(const std::string& text, unsigned size, unsigned min_size, float width) const;
    std::size_t size() const { return texts_.size(); }

    static constexpr std::size_t kMaxEntries = 256;

private:
    sf::Text& get(const std::string& text, unsigned size);

    const sf::Font& font_;
    std::map<std::pair<std::string, unsigned>, sf::Text> texts_;
};

} // namespace carrom::client::app
