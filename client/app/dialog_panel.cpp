#include "dialog_panel.hpp"

#include "draw_util.hpp"
#include "game_over_panel.hpp"
#include "palette.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client::app {
namespace {

const sf::Color kDialogVeil(12, 8, 6, 120);
const sf::Color kDialogCard(28, 18, 12, 240);
const sf::Color kChosenButton(154, 90, 32);

} // namespace

double DialogPanel::draw(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                         const Rect& area, const Dialog& dialog, bool at_top) {
    const bool same = made_for_ && made_for_->dialog == dialog && made_for_->at_top == at_top &&
                      made_for_->area.x == area.x && made_for_->area.y == area.y &&
                      made_for_->area.w == area.w && made_for_->area.h == area.h;
    if (!same) {
        card_h_ = sketch(texts, area, dialog, at_top);
        made_for_ = MadeFor{area, dialog, at_top};
    }
    layer_.draw_overlay(target, blitter, texts, sketch_);
    return card_h_;
}

double DialogPanel::sketch(TextCache& texts, const Rect& area, const Dialog& dialog, bool at_top) {
    sketch_ = Sketch{};
    Sketch& s = sketch_;
    // A card over the board scales with the board; the side area's card is small and keeps its
    // buttons in one row at its right, so that it fits a side area 56 px high.
    const double scale_h = at_top ? 300.0 : area.h;
    const unsigned title_size = scaled_size(scale_h, 0.04, 18.0, 36.0);
    const unsigned body_size = scaled_size(scale_h, 0.022, 12.0, 20.0);
    const double line_h = std::round(body_size * 1.4);
    const double pad = std::round(std::max(8.0, scale_h * 0.022));
    const double gap = std::round(pad * 0.6);
    const double w = at_top ? area.w : std::round(std::min(area.w * 0.9, 680.0));
    const double button_h = std::round(std::clamp(scale_h * 0.05, 30.0, 46.0));
    const auto label_size = static_cast<unsigned>(std::lround(button_h * 0.42));
    std::vector<double> widths;
    double all_w = 0.0;
    for (const std::string& label : dialog.buttons) {
        widths.push_back(
            std::round(static_cast<double>(texts.width(label, label_size)) + button_h * 0.9));
        all_w += widths.back() + gap;
    }
    const double text_w = at_top ? w - 2 * pad - all_w : w - 2 * pad;
    // Several sentences: each a bulleted paragraph, its later rows indented under its text, a
    // little space between paragraphs; an empty sentence is a wider space.
    struct Row {
        std::string text;
        double x = 0.0; // from the card's text edge
        double gap_before = 0.0;
    };
    const bool bullets = dialog.lines.size() > 1;
    const double indent = bullets ? std::round(static_cast<double>(body_size) * 1.2) : 0.0;
    std::vector<Row> lines;
    double text_h = 0.0;
    double gap_next = 0.0;
    for (const std::string& sentence : dialog.lines) {
        if (sentence.empty()) {
            gap_next += line_h * 0.5;
            continue;
        }
        bool first = true;
        for (std::string& l : wrap_text(texts, sentence, body_size, text_w - indent)) {
            lines.push_back({first && bullets ? "\xe2\x80\xa2" : "", 0.0, first ? gap_next : 0.0});
            lines.push_back({std::move(l), indent, 0.0});
            text_h += line_h + (first ? gap_next : 0.0);
            first = false;
        }
        gap_next = bullets ? line_h * 0.25 : 0.0;
    }
    // Over the board the buttons flow into rows that fit the card, each row centred.
    std::vector<std::vector<std::size_t>> rows;
    double row_w = 0.0;
    for (std::size_t i = 0; i < widths.size(); ++i) {
        if (rows.empty() || (!at_top && row_w + gap + widths[i] > w - 2 * pad)) {
            rows.emplace_back();
            row_w = 0.0;
        }
        row_w += (rows.back().empty() ? 0.0 : gap) + widths[i];
        rows.back().push_back(i);
    }
    const double title_h = dialog.title.empty() ? 0.0 : std::round(title_size * 1.5);
    const double rows_h = static_cast<double>(rows.size()) * (button_h + gap);
    const double h = at_top ? std::round(2 * pad + std::max(text_h, button_h))
                            : std::round(pad + title_h + text_h + gap + rows_h + pad * 0.4);
    const Rect card = at_top ? Rect{area.x, area.y, w, std::min(h, area.h)}
                             : Rect{std::round(area.x + (area.w - w) / 2.0),
                                    std::round(area.y + (area.h - h) / 2.0), w, h};
    if (!at_top) {
        s.panel(area, kDialogVeil);
    }
    s.panel(card, kDialogCard, kGold, 2.0f);
    const auto cx = static_cast<float>(card.x + card.w / 2.0);
    double y = at_top ? card.y + (card.h - text_h) / 2.0 : card.y + pad;
    if (!dialog.title.empty()) {
        s.text(dialog.title, title_size, cx, f(y + title_h / 2.0), kGold, Align::Centre);
        y += title_h;
    }
    // Rows come in pairs: the bullet (or nothing), then the text.
    for (std::size_t i = 0; i + 1 < lines.size(); i += 2) {
        y += lines[i].gap_before;
        if (!lines[i].text.empty()) {
            s.text(lines[i].text, body_size, f(card.x + pad), f(y + line_h / 2.0), kGold);
        }
        s.text(lines[i + 1].text, body_size, f(card.x + pad + lines[i + 1].x), f(y + line_h / 2.0),
               kText);
        y += line_h;
    }
    y = at_top ? card.y + (card.h - button_h) / 2.0 : y + gap;
    buttons_.assign(dialog.buttons.size(), Rect{});
    for (const std::vector<std::size_t>& row : rows) {
        double total = 0.0;
        for (const std::size_t i : row) {
            total += widths[i] + (total > 0.0 ? gap : 0.0);
        }
        double x =
            at_top ? card.x + card.w - pad - total : std::round(card.x + (card.w - total) / 2.0);
        for (const std::size_t i : row) {
            const Rect r{std::round(x), std::round(y), widths[i], button_h};
            const bool chosen = static_cast<int>(i) == dialog.chosen;
            s.panel(r, chosen ? kChosenButton : kButton, kGold, chosen ? 2.5f : 1.5f);
            s.text(dialog.buttons[i], label_size, f(r.x + r.w / 2.0), f(r.y + r.h / 2.0), kText,
                   Align::Centre);
            buttons_[i] = r;
            x += widths[i] + gap;
        }
        y += button_h + gap;
    }
    return card.h;
}

std::optional<int> DialogPanel::clicked(const sf::Event& event) const {
    if (event.type != sf::Event::MouseButtonPressed ||
        event.mouseButton.button != sf::Mouse::Left) {
        return std::nullopt;
    }
    const Vec2 p{static_cast<double>(event.mouseButton.x),
                 static_cast<double>(event.mouseButton.y)};
    for (std::size_t i = 0; i < buttons_.size(); ++i) {
        if (buttons_[i].contains(p)) {
            return static_cast<int>(i);
        }
    }
    return std::nullopt;
}

} // namespace carrom::client::app
