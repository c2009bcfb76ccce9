#include "reconnect_panel.hpp"

#include "draw_util.hpp"
#include "game_over_panel.hpp"
#include "palette.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client::app {

namespace {

const sf::Color kVeil(12, 8, 6, 110);
const sf::Color kCard(28, 18, 12, 235);
const sf::Color kWarning(236, 110, 90);

} // namespace

void ReconnectPanel::draw(sf::RenderTarget& target, TextCache& texts, const Rect& b,
                          const ReconnectText& text) const {
    const unsigned title_size = scaled_size(b.h, 0.05, 20.0, 44.0);
    const unsigned body_size = scaled_size(b.h, 0.025, 12.0, 22.0);
    const double line_h = std::round(body_size * 1.45);
    const double w = std::round(std::min(b.w * 0.8, 620.0));
    const double pad = std::round(std::max(12.0, b.h * 0.03));
    std::vector<std::string> lines;
    for (const std::string& sentence : text.lines) {
        for (std::string& l : wrap_text(texts, sentence, body_size, w - 2 * pad)) {
            lines.push_back(std::move(l));
        }
    }
    const double title_h = std::round(title_size * 1.5);
    const double h =
        pad + title_h + line_h * 0.3 + line_h * static_cast<double>(lines.size()) + pad;
    const Rect card{std::round(b.x + (b.w - w) / 2.0), std::round(b.y + (b.h - h) / 2.0), w,
                    std::round(h)};
    const bool gave_up = text.title == "Disconnected";
    draw_panel(target, b, kVeil);
    draw_panel(target, card, kCard, gave_up ? kWarning : kGold, 2.0f);
    const auto cx = static_cast<float>(card.x + card.w / 2.0);
    double y = card.y + pad;
    texts.draw(target, text.title, title_size, cx, static_cast<float>(y + title_h / 2.0),
               gave_up ? kWarning : kGold, Align::Centre);
    y += title_h + line_h * 0.3;
    for (const std::string& line : lines) {
        texts.draw(target, line, body_size, cx, static_cast<float>(y + line_h / 2.0), kText,
                   Align::Centre);
        y += line_h;
    }
}

} // namespace carrom::client::app
