#include "text.hpp"

#include <cmath>

namespace carrom::client::app {

float draw_text(sf::RenderTarget& target, const sf::Font& font, const std::string& text,
                unsigned size, float x, float y_mid, sf::Color colour, Align align) {
    sf::Text t(sf::String::fromUtf8(text.begin(), text.end()), font, size);
    t.setFillColor(colour);
    const sf::FloatRect bounds = t.getLocalBounds();
    float left = x - bounds.left;
    if (align == Align::Centre) {
        left = x - bounds.left - bounds.width / 2.0f;
    } else if (align == Align::Right) {
        left = x - bounds.left - bounds.width;
    }
    // Centre on the line's cap height so mixed sizes line up.
    const float top = y_mid - static_cast<float>(size) * 0.62f;
    t.setPosition(std::round(left), std::round(top));
    target.draw(t);
    return bounds.width;
}

void draw_panel(sf::RenderTarget& target, const Rect& rect, sf::Color fill, sf::Color outline,
                float outline_px) {
    sf::RectangleShape shape({static_cast<float>(rect.w), static_cast<float>(rect.h)});
    shape.setPosition(static_cast<float>(rect.x), static_cast<float>(rect.y));
    shape.setFillColor(fill);
    shape.setOutlineColor(outline);
    shape.setOutlineThickness(outline_px);
    target.draw(shape);
}

} // namespace carrom::client::app
