#include "lobby_view.hpp"

#include "carrom/client/plain_words.hpp"
#include "carrom/proto/limits.hpp"
#include "palette.hpp"
#include "text.hpp"

#include <cctype>

namespace carrom::client::app {
namespace {
const sf::Color kButtonEdge{236, 184, 64};
const sf::Color kLobbyField{240, 228, 200};
} // namespace

Rect LobbyView::control_rect(Control c, const Rect& area) const {
    const double w = std::min(area.w * 0.84, 540.0);
    const double h = std::clamp(area.h * 0.062, 30.0, 50.0);
    const double x0 = area.x + (area.w - w) / 2.0;
    const double gap = h * 0.3;
    const double half = (w - gap) / 2.0;
    const double third = (w * 0.56 - 2.0 * gap) / 2.0;
    const auto row = [&](int n) { return area.y + area.h * 0.2 + n * (h + gap); };
    switch (c) {
    case kName:
        return {x0, row(0), w, h};
    case kRuleSet:
        return {x0, row(1), half, h};
    case kBotLevel:
        return {x0 + half + gap, row(1), half, h};
    case kSingles:
        return {x0 + w * 0.2, row(2), w * 0.3, h * 0.8};
    case kDoubles:
        return {x0 + w * 0.5, row(2), w * 0.3, h * 0.8};
    case kCreate:
        return {x0, row(3) - h * 0.2, half, h};
    case kBot:
        return {x0 + half + gap, row(3) - h * 0.2, half, h};
    case kQuick:
        return {x0, row(4) - h * 0.2, w, h};
    case kCode:
        return {x0, row(5) - h * 0.2, w * 0.44, h};
    case kJoin:
        return {x0 + w * 0.44 + gap, row(5) - h * 0.2, third, h};
    case kWatch:
        return {x0 + w * 0.44 + 2.0 * gap + third, row(5) - h * 0.2, third, h};
    case kHelp:
    case kSettings:
    case kLeaderboard:
    case kMatches: { // four in a row
        const double quarter = (w - 3.0 * gap) / 4.0;
        return {x0 + (c - kHelp) * (quarter + gap), row(6), quarter, h * 0.85};
    }
    case kControlCount:
        break;
    }
    return {};
}

std::vector<Rect> LobbyView::control_rects(const Rect& area) const {
    std::vector<Rect> out;
    for (int c = 0; c < kControlCount; ++c) {
        out.push_back(control_rect(static_cast<Control>(c), area));
    }
    return out;
}

std::string LobbyView::label(Control c) const {
    switch (c) {
    case kName:
        return name_.empty() ? std::string("Your name") : "Name: " + name_;
    case kRuleSet:
        return rule_set_name(rule_set_) + " \xe2\x96\xb8";
    case kBotLevel:
        return "Bot: " + std::string(proto::to_string(bot_level_)) + " \xe2\x96\xb8";
    case kSingles:
        return "Singles";
    case kDoubles:
        return "Doubles";
    case kCreate:
        return "Create room";
    case kBot:
        return seats_ == 4 ? "Play 3 bots" : "Play the bot";
    case kQuick:
        return "Quick match";
    case kCode:
        return code_.empty() ? std::string("ROOM CODE") : code_;
    case kJoin:
        return "Join";
    case kWatch:
        return "Watch";
    case kHelp:
        return "How to play";
    case kSettings:
        return "Settings";
    case kLeaderboard:
        return "Leaderboard";
    case kMatches:
        return "My matches";
    case kControlCount:
        break;
    }
    return "";
}

std::optional<RoomRequest> LobbyView::press(Control c) {
    RoomRequest r;
    r.seats = seats_;
    r.rule_set = rule_set_;
    const bool named = proto::is_player_name(name_);
    switch (c) {
    case kName:
        typing_name_ = true;
        return std::nullopt;
    case kCode:
        typing_name_ = false;
        return std::nullopt;
    case kRuleSet:
        rule_set_ = static_cast<proto::RuleSet>((static_cast<int>(rule_set_) + 1) % 4);
        return std::nullopt;
    case kBotLevel:
        bot_level_ = static_cast<proto::BotLevel>((static_cast<int>(bot_level_) + 1) % 4);
        return std::nullopt;
    case kSingles:
        seats_ = 2;
        return std::nullopt;
    case kDoubles:
        seats_ = 4;
        return std::nullopt;
    case kHelp:
        menu_ = Menu::Rules;
        return std::nullopt;
    case kSettings:
        menu_ = Menu::Settings;
        return std::nullopt;
    case kLeaderboard:
        menu_ = Menu::Leaderboard;
        return std::nullopt;
    case kMatches:
        menu_ = Menu::Matches;
        return std::nullopt;
    case kCreate:
    case kBot:
    case kQuick:
        if (!named) {
            typing_name_ = true;
            return std::nullopt;
        }
        r.kind = c == kQuick ? RoomRequest::Kind::Quick : RoomRequest::Kind::Create;
        if (c == kBot) {
            r.bot = proto::BotSeat{};
            r.bot->level = bot_level_; // doubles: bots in the three other seats
        }
        return r;
    case kJoin:
    case kWatch:
        if (code_.size() != proto::kRoomCodeLength || !named) {
            return std::nullopt;
        }
        r.kind = c == kJoin ? RoomRequest::Kind::Join : RoomRequest::Kind::Spectate;
        r.code = code_;
        r.seats = 2; // the room's own
        return r;
    case kControlCount:
        break;
    }
    return std::nullopt;
}

std::optional<RoomRequest> LobbyView::on_event(const sf::Event& event, const Rect& area) {
    if (event.type == sf::Event::MouseButtonPressed &&
        event.mouseButton.button == sf::Mouse::Left) {
        const Vec2 p{static_cast<double>(event.mouseButton.x),
                     static_cast<double>(event.mouseButton.y)};
        for (int c = 0; c < kControlCount; ++c) {
            if (control_rect(static_cast<Control>(c), area).contains(p)) {
                return press(static_cast<Control>(c));
            }
        }
    } else if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::F2) {
        return press(kLeaderboard);
    } else if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::F3) {
        return press(kMatches);
    } else if (event.type == sf::Event::TextEntered) {
        const auto ch = event.text.unicode;
        std::string& field = typing_name_ ? name_ : code_;
        if (ch == 8 && !field.empty()) {
            field.pop_back();
        } else if (ch == 13) {
            return press(typing_name_ ? kCreate : kJoin);
        } else if (typing_name_ && ch >= 32 && ch < 127 && name_.size() < proto::kMaxNameBytes) {
            name_.push_back(static_cast<char>(ch));
        } else if (!typing_name_ && ch < 128 && std::isalnum(static_cast<int>(ch)) &&
                   code_.size() < proto::kRoomCodeLength) {
            code_.push_back(static_cast<char>(std::toupper(static_cast<int>(ch))));
        }
    }
    return std::nullopt;
}

void LobbyView::draw(sf::RenderTarget& target, const Rect& area, const std::string& status,
                     const std::string& error, bool can_choose, const std::string& rating) const {
    draw_panel(target, area, sf::Color(20, 12, 8, 200));
    const float cx = static_cast<float>(area.x + area.w / 2.0);
    const auto big = static_cast<unsigned>(std::clamp(area.h * 0.08, 24.0, 64.0));
    const auto mid = static_cast<unsigned>(std::clamp(area.h * 0.026, 12.0, 24.0));
    draw_text(target, font_, "Carrom", big, cx, static_cast<float>(area.y + area.h * 0.08),
              kButtonEdge, Align::Centre);
    draw_text(target, font_, status, mid, cx, static_cast<float>(area.y + area.h * 0.15), kDim,
              Align::Centre);
    if (can_choose) {
        for (int c = 0; c < kControlCount; ++c) {
            const auto control = static_cast<Control>(c);
            const Rect r = control_rect(control, area);
            const bool field = c == kCode || c == kName;
            const bool focused = field && (c == kName) == typing_name_;
            const bool doubles = seats_ == 4;
            const bool chosen = (c == kSingles && !doubles) || (c == kDoubles && doubles);
            const bool mode = c == kSingles || c == kDoubles;
            const sf::Color fill = field             ? kLobbyField
                                   : mode && !chosen ? sf::Color(52, 34, 22)
                                                     : kButton;
            draw_panel(target, r, fill, mode && !chosen ? sf::Color(150, 110, 60) : kButtonEdge,
                       chosen || focused ? 2.5f : 1.5f);
            const bool placeholder = (c == kCode && code_.empty()) || (c == kName && name_.empty());
            std::string text = label(control);
            if (focused) {
                text += "_"; // where typing goes
            }
            draw_text(target, font_, text, static_cast<unsigned>(r.h * 0.42),
                      static_cast<float>(r.x + r.w / 2.0), static_cast<float>(r.y + r.h / 2.0),
                      field ? (placeholder ? sf::Color(150, 130, 110) : sf::Color(40, 24, 12))
                            : kText,
                      Align::Centre);
        }
    }
    if (!rating.empty()) {
        const Rect above = control_rect(kLeaderboard, area); // the error line is below
        draw_text(target, font_, rating, mid, cx, static_cast<float>(above.y + above.h + mid * 1.3),
                  kGold, Align::Centre);
    }
    if (!error.empty()) {
        draw_text(target, font_, error, mid, cx, static_cast<float>(area.y + area.h * 0.93),
                  sf::Color(250, 120, 110), Align::Centre);
    }
}

} // namespace carrom::client::app
