#pragma once
// A HUD drawing as plain data: panels, discs and texts in drawing order, in window px. Two
// sketches compare equal exactly when they would draw the same pixels, so a cached layer repaints
// only when what it shows has changed.

#include "carrom/client/screen_mapping.hpp"
#include "text.hpp"

#include <SFML/Graphics.hpp>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

namespace carrom::client::app {

struct SketchPanel {
    Rect rect;
    sf::Color fill;
    sf::Color outline = sf::Color::Transparent;
    float outline_px = 0.0f;
};

struct SketchDisc {
    Vec2 centre;
    double r = 0.0; // window px
    sf::Color colour;
};

struct SketchText {
    std::string text; // UTF-8
    unsigned size = 12;
    float x = 0.0f;     // left, centre or right edge, as `align` says
    float y_mid = 0.0f; // vertical middle of the line
    sf::Color colour;
    Align align = Align::Left;
};

using SketchItem = std::variant<SketchPanel, SketchDisc, SketchText>;

struct Sketch {
    std::vector<SketchItem> items;

    void panel(const Rect& rect, sf::Color fill, sf::Color outline = sf::Color::Transparent,
               float outline_px = 0.0f) {
        items.emplace_back(SketchPanel{rect, fill, outline, outline_px});
    }
    // A panel w x h centred on `around`, its corner on whole px; returns where it lies.
    Rect centred_panel(const Rect& around, double w, double h, sf::Color fill, sf::Color outline,
                       float outline_px) {
        const Rect rect{std::round(around.x + (around.w - w) / 2.0),
                        std::round(around.y + (around.h - h) / 2.0), w, std::round(h)};
        panel(rect, fill, outline, outline_px);
        return rect;
    }
    void disc(Vec2 centre, double r, sf::Color colour) {
        items.emplace_back(SketchDisc{centre, r, colour});
    }
    void text(std::string s, unsigned size, float x, float y_mid, sf::Color colour,
              Align align = Align::Left) {
        items.emplace_back(SketchText{std::move(s), size, x, y_mid, colour, align});
    }
};

bool operator==(const SketchPanel& a, const SketchPanel& b);
bool operator==(const SketchDisc& a, const SketchDisc& b);
bool operator==(const SketchText& a, const SketchText& b);
bool operator==(const Sketch& a, const Sketch& b);

// Draws the items in order; texts are laid out through `texts` (glyphs built once per string).
void draw_sketch(sf::RenderTarget& target, TextCache& texts, const Sketch& sketch);

} // namespace carrom::client::app
