#include "text.hpp"

#include <algorithm>
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

FittedText TextCache::fit(const std::string& text, unsigned size, unsigned min_size,
                          float width) const {
    sf::Text t(sf::String::fromUtf8(text.begin(), text.end()), font_, size);
    for (unsigned s = size; s >= min_size && s > 0; --s) {
        t.setCharacterSize(s);
        if (t.getLocalBounds().width <= width) {
            return {text, s};
        }
    }
    const unsigned s = std::max(min_size, 1u);
    t.setCharacterSize(s);
    sf::String kept = sf::String::fromUtf8(text.begin(), text.end()); // code points
    while (!kept.isEmpty()) {
        kept.erase(kept.getSize() - 1);
        // No space before the dots ("Bot Kiran..." rather than "Bot Kiran ...").
        while (!kept.isEmpty() && kept[kept.getSize() - 1] == U' ') {
            kept.erase(kept.getSize() - 1);
        }
        t.setString(kept + sf::String("..."));
        if (t.getLocalBounds().width <= width) {
            break;
        }
    }
    const std::basic_string<sf::Uint8> utf8 = (kept + sf::String("...")).toUtf8();
    return {std::string(utf8.begin(), utf8.end()), s};
}

} // namespace carrom::client::app
