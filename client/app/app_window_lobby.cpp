#include "app_window.hpp"

#include "network_link.hpp"
#include "replay_view.hpp"

#include <iostream>
#include <utility>

namespace carrom::client::app {

void AppWindow::handle_lobby_event(const sf::Event& e) {
    if (lobby_page_ == LobbyPage::Leaderboard) {
        switch (leaderboard_view_.on_event(e, lobby_area())) {
        case LeaderboardView::Action::Back:
            lobby_page_ = LobbyPage::Main;
            break;
        case LeaderboardView::Action::Read:
            records_.read_leaderboard(leaderboard_view_.rule_set());
            break;
        case LeaderboardView::Action::None:
            break;
        }
        return;
    }
    if (lobby_page_ == LobbyPage::Matches) {
        const MatchListView::Action action =
            match_list_.on_event(e, lobby_area(), records_.matches());
        if (action.back) {
            lobby_page_ = LobbyPage::Main;
            journal_asked_ = false;
        } else if (const auto* record = std::get_if<PlayerRecord>(&records_.matches());
                   action.open && record != nullptr && *action.open < record->matches.size()) {
            records_.read_journal(record->matches[*action.open].replay);
            journal_asked_ = true;
        }
        return;
    }
    if (auto request = lobby_.on_event(e, lobby_area())) {
        if (lobby_.name() != options_.name) {
            // Another name: a new player on a new connection.
            options_.name = lobby_.name();
            session_ = ClientSession(
                make_factory(), options_.name,
                network_session_config(options_.identity, options_.demo ? "" : options_.url));
            session_.start(clock_.now());
        }
        session_.request(*request);
    }
    switch (lobby_.take_menu()) {
    case LobbyView::Menu::Rules:
        menus_.open_rules(lobby_.rule_set());
        break;
    case LobbyView::Menu::Settings:
        menus_.open_settings();
        break;
    case LobbyView::Menu::Leaderboard:
        lobby_page_ = LobbyPage::Leaderboard;
        leaderboard_view_.set_rule_set(lobby_.rule_set());
        records_.read_leaderboard(lobby_.rule_set());
        break;
    case LobbyView::Menu::Matches:
        lobby_page_ = LobbyPage::Matches;
        journal_asked_ = false;
        records_.read_matches(options_.name);
        break;
    case LobbyView::Menu::None:
        break;
    }
}

void AppWindow::draw_lobby(const std::string& error, bool can_choose) {
    switch (lobby_page_) {
    case LobbyPage::Leaderboard:
        draw_list_page(window_, font_, lobby_area(),
                       leaderboard_view_.page(records_.leaderboard()));
        return;
    case LobbyPage::Matches:
        draw_list_page(window_, font_, lobby_area(),
                       match_list_.page(options_.name, records_.matches(),
                                        journal_asked_ ? std::optional(records_.journal_state())
                                                       : std::nullopt));
        return;
    case LobbyPage::Main:
        break;
    }
    lobby_.draw(window_, lobby_area(), session_.status_text(), error, can_choose,
                records_.book().lobby_line(options_.name));
}

void AppWindow::update_records(double now) {
    const bool lobby = session_.phase() == SessionPhase::Lobby;
    if (lobby && !in_lobby_ && !options_.demo) {
        records_.lobby_entered(options_.name, now);
    }
    in_lobby_ = lobby;
    if (!lobby) {
        lobby_page_ = LobbyPage::Main; // a room was asked for (or the link went)
    }
    const MatchView& v = model_.view();
    if (v.in_room && !options_.demo) {
        records_.room_seen(v, now);
    }
    records_.update(now);
    hud_.set_seat_ratings(seat_rating_texts());
    if (auto replay = records_.take_journal()) {
        open_replay(std::move(*replay));
    }
}

void AppWindow::open_replay(ReplayModel replay) {
    journal_asked_ = false;
    // The replay window holds this window's unattended modes but the input script (--final-state
    // at the replay's end, --screenshot, --timeout): when one of them ends the replay, it ends the
    // run with its exit code. A player's closing of the replay returns to the lobby.
    AppOptions replay_options = options_;
    replay_options.input_script.clear();
    replay_options.request.reset();
    replay_options.width = window_.getSize().x;
    replay_options.height = window_.getSize().y;
    const bool unattended = !options_.final_state_path.empty() ||
                            !options_.screenshot_path.empty() || options_.timeout_s > 0.0;
    window_.setVisible(false);
    const int code = run_replay(replay_options, std::move(replay));
    window_.setVisible(true);
    if (unattended) {
        replay_exit_ = code;
    }
}

std::vector<std::string> AppWindow::seat_rating_texts() const {
    const MatchView& v = model_.view();
    std::vector<std::string> texts;
    if (v.seats.size() > 2) {
        return std::vector<std::string>(v.seats.size()); // doubles are not rated
    }
    for (const SeatView& s : v.seats) {
        texts.push_back(
            s.occupied && !s.bot
                ? records_.book().seat_text(s.name, std::string(proto::to_string(v.rule_set)))
                : "");
    }
    return texts;
}

GameOverText AppWindow::game_over_words() const {
    GameOverText text = game_over_text(model_.view(), rematch_asked_);
    // The game's players, also one who has left the room since.
    const std::string rule_set(proto::to_string(model_.view().rule_set));
    for (const std::string& name : records_.seat_players()) {
        if (name.empty() || !records_.book().changed(name, rule_set)) {
            continue;
        }
        const std::string rating = records_.book().seat_text(name, rule_set);
        if (!rating.empty()) {
            text.ratings += (text.ratings.empty() ? "Ratings: " : ", ") + name + " " + rating;
        }
    }
    return text;
}

nlohmann::json AppWindow::records_json() const {
    const char* page = lobby_page_ == LobbyPage::Leaderboard ? "leaderboard"
                       : lobby_page_ == LobbyPage::Matches   ? "matches"
                                                             : "main";
    ListPage shown;
    if (lobby_page_ == LobbyPage::Leaderboard) {
        shown = leaderboard_view_.page(records_.leaderboard());
    } else if (lobby_page_ == LobbyPage::Matches) {
        shown = match_list_.page(options_.name, records_.matches(),
                                 journal_asked_ ? std::optional(records_.journal_state())
                                                : std::nullopt);
    }
    return {{"page", page},
            {"rating_line", records_.book().lobby_line(options_.name)},
            {"note", shown.note},
            {"rows", shown.rows},
            {"seat_ratings", seat_rating_texts()},
            {"game_over_ratings", game_over_words().ratings}};
}

} // namespace carrom::client::app
