#include "game_over_panel.hpp"

#include "draw_util.hpp"
#include "palette.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client::app {
namespace {

const sf::Color kPanel{24, 14, 8, 232};
const sf::Color kButtonOff{58, 40, 28};

// Greedy line filling: each line takes words while it fits in `width`.
std::vector<std::string> fill_lines(TextCache& texts, const std::vector<std::string>& words,
                                    unsigned size, double width) {
    std::vector<std::string> lines;
    std::string line;
    for (const std::string& word : words) {
        const std::string longer = line.empty() ? word : line + " " + word;
        if (!line.empty() && static_cast<double>(texts.width(longer, size)) > width) {
            lines.push_back(line);
            line = word;
        } else {
            line = longer;
        }
    }
    if (!line.empty()) {
        lines.push_back(line);
    }
    return lines;
}

} // namespace

std::vector<std::string> wrap_text(TextCache& texts, const std::string& text, unsigned size,
                                   double width) {
    std::vector<std::string> words;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find(' ', start);
        end = end == std::string::npos ? text.size() : end;
        if (end > start) {
            words.push_back(text.substr(start, end - start));
        }
        start = end + 1;
    }
    std::vector<std::string> lines = fill_lines(texts, words, size, width);
    // Narrow the width in steps of 2 % while the line count stays: no short last line.
    for (double w = width * 0.98; lines.size() > 1 && w > width * 0.3; w *= 0.98) {
        std::vector<std::string> narrower = fill_lines(texts, words, size, w);
        if (narrower.size() != lines.size()) {
            break;
        }
        lines = std::move(narrower);
    }
    return lines;
}

Sketch GameOverPanel::sketch(TextCache& texts, const Rect& b, const GameOverText& text) {
    const unsigned title_size = scaled_size(b.h, 0.062, 22.0, 56.0);
    const unsigned body_size = scaled_size(b.h, 0.027, 13.0, 24.0);
    const double line_h = std::round(body_size * 1.45);
    const double button_h = std::round(std::clamp(b.h * 0.064, 32.0, 54.0));
    const double w = std::round(std::min(b.w * 0.84, 680.0));
    const double pad = std::round(std::max(14.0, b.h * 0.035));
    const std::vector<std::string> reason = wrap_text(texts, text.reason, body_size, w - 2 * pad);
    const std::vector<std::string> waiting = wrap_text(texts, text.waiting, body_size, w - 2 * pad);
    // Title, a gap, the reason, the score, a gap, the waiting line (if any), the buttons.
    const double title_h = std::round(title_size * 1.5);
    const double ratings_h = text.ratings.empty() ? 0.0 : line_h;
    const double h = pad + title_h + line_h * 0.4 + line_h * static_cast<double>(reason.size()) +
                     line_h + ratings_h + line_h * 0.8 +
                     line_h * static_cast<double>(waiting.size()) +
                     (waiting.empty() ? 0.0 : line_h * 0.4) + button_h + pad;
    Sketch s;
    const Rect panel = s.centred_panel(b, w, h, kPanel, kGold, 2.0f);
    const auto cx = static_cast<float>(panel.x + panel.w / 2.0);
    double y = panel.y + pad;
    s.text(text.title, title_size, cx, static_cast<float>(y + title_h / 2.0), kGold, Align::Centre);
    y += title_h + line_h * 0.4;
    for (const std::string& line : reason) {
        s.text(line, body_size, cx, static_cast<float>(y + line_h / 2.0), kText, Align::Centre);
        y += line_h;
    }
    s.text(text.score, body_size, cx, static_cast<float>(y + line_h / 2.0), kDim, Align::Centre);
    y += line_h;
    if (!text.ratings.empty()) {
        s.text(text.ratings, body_size, cx, static_cast<float>(y + line_h / 2.0), kGold,
               Align::Centre);
        y += ratings_h;
    }
    y += line_h * 0.8;
    for (const std::string& line : waiting) {
        s.text(line, body_size, cx, static_cast<float>(y + line_h / 2.0), kDim, Align::Centre);
        y += line_h;
    }
    y += waiting.empty() ? 0.0 : line_h * 0.4;
    // The buttons: [Rematch (R)] [Lobby (L)] for a player, [Lobby (L)] for a spectator.
    const bool player = (text.can_rematch || !text.waiting.empty()) && !text.opponent_left;
    const double gap = std::round(pad * 0.8);
    const double button_w = std::round(player ? (w - 2 * pad - gap) / 2.0 : (w - 2 * pad) / 2.0);
    const unsigned label_size = static_cast<unsigned>(std::lround(button_h * 0.42));
    auto button = [&](const Rect& r, const std::string& label, bool enabled) {
        s.panel(r, enabled ? kButton : kButtonOff, enabled ? kGold : kDim, enabled ? 1.5f : 1.0f);
        s.text(label, label_size, static_cast<float>(r.x + r.w / 2.0),
               static_cast<float>(r.y + r.h / 2.0), enabled ? kText : kDim, Align::Centre);
    };
    rematch_button_.reset();
    if (player) {
        const Rect r{panel.x + pad, std::round(y), button_w, button_h};
        button(r, text.can_rematch ? "Rematch (R)" : "Rematch asked", text.can_rematch);
        if (text.can_rematch) {
            rematch_button_ = r;
        }
        lobby_button_ = Rect{panel.x + panel.w - pad - button_w, std::round(y), button_w, button_h};
    } else {
        lobby_button_ = Rect{std::round(panel.x + (panel.w - button_w) / 2.0), std::round(y),
                             button_w, button_h};
    }
    button(*lobby_button_, "Lobby (L)", true);
    return s;
}

void GameOverPanel::draw(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                         const Rect& board, const GameOverText& text) {
    const Sketch& s = sketch_.get(
        board, text, [&](const Rect& b, const GameOverText& t) { return sketch(texts, b, t); });
    layer_.draw_overlay(target, blitter, texts, s);
}

std::optional<GameOverPanel::Choice> GameOverPanel::on_event(const sf::Event& e,
                                                             const GameOverText& text) const {
    if (e.type == sf::Event::KeyPressed) {
        if (e.key.code == sf::Keyboard::R && text.can_rematch) {
            return Choice::Rematch;
        }
        if (e.key.code == sf::Keyboard::L || e.key.code == sf::Keyboard::Escape) {
            return Choice::Lobby;
        }
        return std::nullopt;
    }
    if (e.type == sf::Event::MouseButtonPressed && e.mouseButton.button == sf::Mouse::Left) {
        const Vec2 p{static_cast<double>(e.mouseButton.x), static_cast<double>(e.mouseButton.y)};
        if (rematch_button_ && text.can_rematch && rematch_button_->contains(p)) {
            return Choice::Rematch;
        }
        if (lobby_button_ && lobby_button_->contains(p)) {
            return Choice::Lobby;
        }
    }
    return std::nullopt;
}

} // namespace carrom::client::app
