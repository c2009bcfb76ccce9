#include "text.hpp"

#include <cmath>

namespace carrom::client::app {
namespace {

// Positions a laid-out text: its left/centre/right edge at x, the cap height's middle at y_mid
// (so mixed sizes line up).
void place(sf::Text& t, unsigned size, float x, float y_mid, Align align) {
    const sf::FloatRect bounds = t.getLocalBounds();
    float left = x - bounds.left;
    if (align == Align::Centre) {
        left = x - bounds.left - bounds.width / 2.0f;
    } else if (align == Align::Right) {
        left = x - bounds.left - bounds.width;
    }
    const float top = y_mid - static_cast<float>(size) * 0.62f;
    t.setPosition(std::round(left), std::round(top));
}

} // namespace

float draw_text(sf::RenderTarget& target, const sf::Font& font, const std::string& text,
                unsigned size, float x, float y_mid, sf::Color colour, Align align) {
    sf::Text t(sf::String::fromUtf8(text.begin(), text.end()), font, size);
    t.setFillColor(colour);
    place(t, size, x, y_mid, align);
    target.draw(t);
    return t.getLocalBounds().width;
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

sf::Text& TextCache::get(const std::string& text, unsigned size) {
    auto key = std::make_pair(text, size);
    if (auto it = texts_.find(key); it != texts_.end()) {
        return it->second;
    }
    if (texts_.size() >= kMaxEntries) {
        texts_.clear();
    }
    sf::Text t(sf::String::fromUtf8(text.begin(), text.end()), font_, size);
    return texts_.emplace(std::move(key), std::move(t)).first->second;
}

float TextCache::draw(sf::RenderTarget& target, const std::string& text, unsigned size, float x,
                      float y_mid, sf::Color colour, Align align) {
    sf::Text& t = get(text, size);
    t.setFillColor(colour);
    place(t, size, x, y_mid, align);
    target.draw(t);
    return t.getLocalBounds().width;
}

float TextCache::width(const std::string& text, unsigned size) {
    return get(text, size).getLocalBounds().width;
}

} // namespace carrom::client::app
