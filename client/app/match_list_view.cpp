#include "match_list_view.hpp"

#include "carrom/client/plain_words.hpp"
#include "carrom/client/rating_book.hpp"
#include "carrom/client/rating_words.hpp"

#include <algorithm>

namespace carrom::client::app {

namespace {

std::size_t rows_shown(const ServerRecords::Reading<PlayerRecord>& reading) {
    const auto* record = std::get_if<PlayerRecord>(&reading);
    return record == nullptr
               ? 0
               : std::min(record->matches.size(), static_cast<std::size_t>(kListPageRows));
}

} // namespace

std::vector<Rect>
MatchListView::control_rects(const Rect& area,
                             const ServerRecords::Reading<PlayerRecord>& reading) const {
    std::vector<Rect> rects{list_button_rect(area, 0, 1)};
    for (std::size_t i = 0; i < rows_shown(reading); ++i) {
        rects.push_back(list_row_rect(area, static_cast<int>(i)));
    }
    return rects;
}

MatchListView::Action
MatchListView::on_event(const sf::Event& event, const Rect& area,
                        const ServerRecords::Reading<PlayerRecord>& reading) const {
    Action action;
    if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::Escape) {
        action.back = true;
    }
    if (event.type == sf::Event::MouseButtonPressed &&
        event.mouseButton.button == sf::Mouse::Left) {
        const Vec2 p{static_cast<double>(event.mouseButton.x),
                     static_cast<double>(event.mouseButton.y)};
        const std::vector<Rect> rects = control_rects(area, reading);
        for (std::size_t i = 0; i < rects.size(); ++i) {
            if (rects[i].contains(p)) {
                if (i == 0) {
                    action.back = true;
                } else {
                    action.open = i - 1;
                }
            }
        }
    }
    return action;
}

ListPage MatchListView::page(const std::string& name,
                             const ServerRecords::Reading<PlayerRecord>& reading,
                             const std::optional<ServerRecords::Reading<bool>>& journal) const {
    ListPage page;
    page.title = "My matches";
    page.buttons = {"Back"};
    page.columns = {{"Opponent", 0.0, Align::Left},
                    {"Rules", 0.36, Align::Left},
                    {"Result", 0.52, Align::Left},
                    {"Date", 1.0, Align::Right}};
    page.rows_are_buttons = true;
    if (std::holds_alternative<std::monostate>(reading)) {
        page.note = "Reading the matches of " + name + "...";
        return page;
    }
    if (const auto* problem = std::get_if<std::string>(&reading)) {
        page.note = *problem;
        page.note_is_error = true;
        return page;
    }
    const PlayerRecord& record = std::get<PlayerRecord>(reading);
    page.note = record.matches.empty()
                    ? "No matches of " + name +
                          " on this server yet (only identified players' "
                          "matches are listed)."
                    : "The last matches of " + name + ", newest first: click one to replay it";
    for (std::size_t i = 0; i < rows_shown(reading); ++i) {
        const MatchEntry& m = record.matches[i];
        const MatchLine line = match_line(m, name);
        page.rows.push_back(
            {line.opponent, rating_rule_set_word(m.rule_set), line.result, line.date});
    }
    if (journal) {
        if (std::holds_alternative<std::monostate>(*journal)) {
            page.note = "Reading the match's journal...";
        } else if (const auto* problem = std::get_if<std::string>(&*journal)) {
            page.note = *problem;
            page.note_is_error = true;
        }
    }
    return page;
}

} // namespace carrom::client::app
