#include "lobby_view.hpp"

#include "carrom/proto/limits.hpp"
#include "palette.hpp"
#include "text.hpp"

#include <cctype>

namespace carrom::client::app {
namespace {
const sf::Color kButtonEdge{236, 184, 64};
} // namespace

Rect LobbyView::control_rect(Control c, const Rect& area) const {
    const double w = std::min(area.w * 0.8, 520.0);
    const double h = std::clamp(area.h * 0.07, 34.0, 56.0);
    const double x0 = area.x + (area.w - w) / 2.0;
    const double gap = h * 0.35;
    const double y0 = area.y + area.h * 0.35 + h * 0.8 + gap;
    const double half = (w - gap) / 2.0;
    switch (c) {
    case kSingles:
        return {x0 + w * 0.2, y0 - h * 0.8 - gap, w * 0.3, h * 0.8};
    case kDoubles:
        return {x0 + w * 0.5, y0 - h * 0.8 - gap, w * 0.3, h * 0.8};
    case kCreate:
        return {x0, y0, half, h};
    case kBot:
        return {x0 + half + gap, y0, half, h};
    case kQuick:
        return {x0, y0 + (h + gap), w, h};
    case kCode:
        return {x0, y0 + 2.0 * (h + gap), w * 0.44, h};
    case kJoin:
        return {x0 + w * 0.44 + gap, y0 + 2.0 * (h + gap), (w * 0.56 - 2.0 * gap) / 2.0, h};
    case kWatch:
        return {x0 + w * 0.44 + gap + (w * 0.56 - 2.0 * gap) / 2.0 + gap, y0 + 2.0 * (h + gap),
                (w * 0.56 - 2.0 * gap) / 2.0, h};
    case kControlCount:
        break;
    }
    return {};
}

std::optional<RoomRequest> LobbyView::press(Control c) {
    RoomRequest r;
    r.seats = seats_;
    switch (c) {
    case kSingles:
        seats_ = 2;
        return std::nullopt;
    case kDoubles:
        seats_ = 4;
        return std::nullopt;
    case kCreate:
        r.kind = RoomRequest::Kind::Create;
        return r;
    case kBot:
        r.kind = RoomRequest::Kind::Create;
        r.bot = proto::BotSeat{};
        r.bot->level = proto::BotLevel::Medium; // doubles: bots in the three other seats
        return r;
    case kQuick:
        r.kind = RoomRequest::Kind::Quick;
        return r;
    case kJoin:
    case kWatch:
        if (code_.size() != proto::kRoomCodeLength) {
            return std::nullopt;
        }
        r.kind = c == kJoin ? RoomRequest::Kind::Join : RoomRequest::Kind::Spectate;
        r.code = code_;
        r.seats = 2; // the room's own
        return r;
    case kCode:
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
    } else if (event.type == sf::Event::TextEntered) {
        const auto ch = event.text.unicode;
        if (ch == 8 && !code_.empty()) {
            code_.pop_back();
        } else if (ch == 13) {
            return press(kJoin);
        } else if (ch < 128 && std::isalnum(static_cast<int>(ch)) &&
                   code_.size() < proto::kRoomCodeLength) {
            code_.push_back(static_cast<char>(std::toupper(static_cast<int>(ch))));
        }
    }
    return std::nullopt;
}

void LobbyView::draw(sf::RenderTarget& target, const Rect& area, const std::string& name,
                     const std::string& status, const std::string& error, bool can_choose) const {
    draw_panel(target, area, sf::Color(20, 12, 8, 200));
    const float cx = static_cast<float>(area.x + area.w / 2.0);
    const auto big = static_cast<unsigned>(std::clamp(area.h * 0.09, 24.0, 72.0));
    const auto mid = static_cast<unsigned>(std::clamp(area.h * 0.03, 13.0, 26.0));
    draw_text(target, font_, "Carrom", big, cx, static_cast<float>(area.y + area.h * 0.16),
              kButtonEdge, Align::Centre);
    draw_text(target, font_, "Playing as " + name, mid, cx,
              static_cast<float>(area.y + area.h * 0.25), kText, Align::Centre);
    draw_text(target, font_, status, mid, cx, static_cast<float>(area.y + area.h * 0.30), kDim,
              Align::Centre);
    if (can_choose) {
        const bool doubles = seats_ == 4;
        const char* labels[kControlCount] = {
            "Singles",     "Doubles", "Create room", doubles ? "Play 3 bots" : "Play the bot",
            "Quick match", "",        "Join",        "Watch"};
        for (int c = 0; c < kControlCount; ++c) {
            const Rect r = control_rect(static_cast<Control>(c), area);
            const bool field = c == kCode;
            const bool chosen = (c == kSingles && !doubles) || (c == kDoubles && doubles);
            const bool mode = c == kSingles || c == kDoubles;
            const sf::Color fill = field             ? sf::Color(240, 228, 200)
                                   : mode && !chosen ? sf::Color(52, 34, 22)
                                                     : kButton;
            draw_panel(target, r, fill, mode && !chosen ? sf::Color(150, 110, 60) : kButtonEdge,
                       chosen ? 2.5f : 1.5f);
            const std::string label =
                field ? (code_.empty() ? std::string("ROOM CODE") : code_) : labels[c];
            draw_text(target, font_, label, static_cast<unsigned>(r.h * 0.45),
                      static_cast<float>(r.x + r.w / 2.0), static_cast<float>(r.y + r.h / 2.0),
                      field ? (code_.empty() ? sf::Color(150, 130, 110) : sf::Color(40, 24, 12))
                            : kText,
                      Align::Centre);
        }
    }
    if (!error.empty()) {
        draw_text(target, font_, error, mid, cx, static_cast<float>(area.y + area.h * 0.74),
                  sf::Color(250, 120, 110), Align::Centre);
    }
}

} // namespace carrom::client::app
