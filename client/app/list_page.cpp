#include "list_page.hpp"

#include "palette.hpp"

#include <algorithm>

namespace carrom::client::app {

namespace {

double page_width(const Rect& area) {
    return std::min(area.w * 0.9, 640.0);
}

} // namespace

Rect list_button_rect(const Rect& area, int i, int count) {
    const double w = page_width(area);
    const double x0 = area.x + (area.w - w) / 2.0;
    const double h = std::clamp(area.h * 0.055, 28.0, 44.0);
    const double gap = h * 0.3;
    const double bw = (w - gap * (count - 1)) / count;
    return {x0 + i * (bw + gap), area.y + area.h * 0.19, bw, h};
}

Rect list_row_rect(const Rect& area, int i) {
    const double w = page_width(area);
    const double h = area.h * 0.6 / kListPageRows;
    return {area.x + (area.w - w) / 2.0, area.y + area.h * 0.31 + i * h, w, h};
}

void draw_list_page(sf::RenderTarget& target, const sf::Font& font, const Rect& area,
                    const ListPage& page) {
    draw_panel(target, area, sf::Color(20, 12, 8, 200));
    const float cx = static_cast<float>(area.x + area.w / 2.0);
    const auto big = static_cast<unsigned>(std::clamp(area.h * 0.06, 20.0, 48.0));
    const auto mid = static_cast<unsigned>(std::clamp(area.h * 0.024, 12.0, 22.0));
    draw_text(target, font, page.title, big, cx, static_cast<float>(area.y + area.h * 0.08), kGold,
              Align::Centre);
    draw_text(target, font, page.note, mid, cx, static_cast<float>(area.y + area.h * 0.145),
              page.note_is_error ? sf::Color(250, 120, 110) : kDim, Align::Centre);
    const int count = static_cast<int>(page.buttons.size());
    for (int i = 0; i < count; ++i) {
        const Rect r = list_button_rect(area, i, count);
        draw_panel(target, r, kButton, kGold, 1.5f);
        draw_text(target, font, page.buttons[static_cast<std::size_t>(i)],
                  static_cast<unsigned>(r.h * 0.42), static_cast<float>(r.x + r.w / 2.0),
                  static_cast<float>(r.y + r.h / 2.0), kText, Align::Centre);
    }
    const Rect first = list_row_rect(area, 0);
    const auto row_size = static_cast<unsigned>(std::max(11.0, first.h * 0.55));
    const auto column_x = [&](const ListColumn& c) {
        return static_cast<float>(first.x + 10.0 + c.x * (first.w - 20.0));
    };
    for (const ListColumn& c : page.columns) {
        draw_text(target, font, c.header, row_size, column_x(c),
                  static_cast<float>(first.y - first.h * 0.6), kGold, c.align);
    }
    const int rows = std::min(static_cast<int>(page.rows.size()), kListPageRows);
    for (int i = 0; i < rows; ++i) {
        const Rect r = list_row_rect(area, i);
        const Rect inner{r.x, r.y + 1.0, r.w, r.h - 2.0};
        if (page.rows_are_buttons) {
            draw_panel(target, inner, sf::Color(52, 34, 22), sf::Color(150, 110, 60), 1.0f);
        } else if (i % 2 == 0) {
            draw_panel(target, inner, sf::Color(52, 34, 22, 160));
        }
        const auto& cells = page.rows[static_cast<std::size_t>(i)];
        for (std::size_t c = 0; c < page.columns.size() && c < cells.size(); ++c) {
            draw_text(target, font, cells[c], row_size, column_x(page.columns[c]),
                      static_cast<float>(r.y + r.h / 2.0), kText, page.columns[c].align);
        }
    }
}

} // namespace carrom::client::app
