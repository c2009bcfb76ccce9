#include "board_summary_panel.hpp"

#include "draw_util.hpp"
#include "palette.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client::app {

Sketch BoardSummaryPanel::sketch(const Rect& b, const BoardSummaryText& text) const {
    const sf::Color fill{24, 14, 8, 232};
    const unsigned title_size = scaled_size(b.h, 0.05, 20.0, 44.0);
    const unsigned body_size = scaled_size(b.h, 0.027, 13.0, 24.0);
    const double line_h = std::round(body_size * 1.5);
    const double title_h = std::round(title_size * 1.5);
    const double pad = std::round(std::max(14.0, b.h * 0.03));
    const double w = std::round(std::min(b.w * 0.8, 620.0));
    const int lines = 2 + (text.colours.empty() ? 0 : 1);
    const double h = pad + title_h + line_h * lines + pad;
    Sketch s;
    const Rect panel = s.centred_panel(b, w, h, fill, kGold, 2.0f);
    const auto cx = static_cast<float>(panel.x + panel.w / 2.0);
    double y = panel.y + pad;
    s.text(text.title, title_size, cx, static_cast<float>(y + title_h / 2.0), kGold, Align::Centre);
    y += title_h;
    s.text(text.points, body_size, cx, static_cast<float>(y + line_h / 2.0), kText, Align::Centre);
    y += line_h;
    if (!text.colours.empty()) {
        s.text(text.colours, body_size, cx, static_cast<float>(y + line_h / 2.0), kText,
               Align::Centre);
        y += line_h;
    }
    s.text("Click or press a key to play on", body_size, cx, static_cast<float>(y + line_h / 2.0),
           kDim, Align::Centre);
    return s;
}

void BoardSummaryPanel::draw(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                             const Rect& board, const BoardSummaryText& text) {
    const Sketch& s = sketch_.get(
        board, text, [this](const Rect& b, const BoardSummaryText& t) { return sketch(b, t); });
    layer_.draw_overlay(target, blitter, texts, s);
}

bool BoardSummaryPanel::dismisses(const sf::Event& e) {
    return e.type == sf::Event::KeyPressed ||
           (e.type == sf::Event::MouseButtonPressed && e.mouseButton.button == sf::Mouse::Left);
}

} // namespace carrom::client::app
