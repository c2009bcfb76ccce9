#include "leaderboard_view.hpp"

#include "carrom/client/plain_words.hpp"
#include "carrom/client/rating_words.hpp"

namespace carrom::client::app {

std::vector<Rect> LeaderboardView::control_rects(const Rect& area) const {
    return {list_button_rect(area, 0, 2), list_button_rect(area, 1, 2)};
}

LeaderboardView::Action LeaderboardView::on_event(const sf::Event& event, const Rect& area) {
    const auto next_rule_set = [this] {
        rule_set_ = static_cast<proto::RuleSet>((static_cast<int>(rule_set_) + 1) % 4);
        return Action::Read;
    };
    if (event.type == sf::Event::KeyPressed) {
        if (event.key.code == sf::Keyboard::Escape) {
            return Action::Back;
        }
        if (event.key.code == sf::Keyboard::Tab) {
            return next_rule_set();
        }
    }
    if (event.type == sf::Event::MouseButtonPressed &&
        event.mouseButton.button == sf::Mouse::Left) {
        const Vec2 p{static_cast<double>(event.mouseButton.x),
                     static_cast<double>(event.mouseButton.y)};
        const std::vector<Rect> rects = control_rects(area);
        if (rects[0].contains(p)) {
            return next_rule_set();
        }
        if (rects[1].contains(p)) {
            return Action::Back;
        }
    }
    return Action::None;
}

ListPage LeaderboardView::page(const ServerRecords::Reading<Leaderboard>& reading) const {
    ListPage page;
    page.title = "Leaderboard";
    page.buttons = {rule_set_name(rule_set_) + " \xe2\x96\xb8", "Back"};
    page.columns = {{"#", 0.06, Align::Right},
                    {"Player", 0.12, Align::Left},
                    {"Rating", 0.78, Align::Right},
                    {"Games", 0.98, Align::Right}};
    if (std::holds_alternative<std::monostate>(reading)) {
        page.note = "Reading the leaderboard...";
    } else if (const auto* problem = std::get_if<std::string>(&reading)) {
        page.note = *problem;
        page.note_is_error = true;
    } else {
        const Leaderboard& board = std::get<Leaderboard>(reading);
        // The web page's words for an empty board (rating_words.js, leaderboardView).
        page.note = board.rows.empty()
                        ? "Nobody has an established " +
                              rating_rule_set_word(std::string(proto::to_string(rule_set_))) +
                              " rating yet (it takes about 10 rated games)."
                        : "Established ratings in " + rule_set_name(rule_set_) + ", best first";
        for (const LeaderboardRow& row : board.rows) {
            if (page.rows.size() == static_cast<std::size_t>(kListPageRows)) {
                break;
            }
            page.rows.push_back({std::to_string(row.rank), row.name, row.rating.label,
                                 std::to_string(row.rating.games)});
        }
    }
    return page;
}

} // namespace carrom::client::app
