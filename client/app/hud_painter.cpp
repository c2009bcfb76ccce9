#include "hud_painter.hpp"

#include "board_painter.hpp"
#include "carrom/client/plain_words.hpp"
#include "draw_util.hpp"
#include "game_over_panel.hpp"
#include "palette.hpp"
#include "text.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace carrom::client::app {
namespace {

const sf::Color kBar{36, 22, 14};
const sf::Color kAlert{236, 84, 64};
const sf::Color kOk{120, 200, 120};

unsigned text_size(double bar_h, double k) {
    return static_cast<unsigned>(std::max(10.0, std::round(bar_h * k)));
}

std::string colour_word(proto::Colour c) {
    switch (c) {
    case proto::Colour::Black:
        return "black";
    case proto::Colour::White:
        return "white";
    case proto::Colour::None:
        break;
    }
    return "";
}

sf::Color tone_colour(Tone tone) {
    switch (tone) {
    case Tone::Good:
        return {150, 220, 140};
    case Tone::Foul:
        return {250, 190, 90};
    case Tone::Error:
        return {250, 120, 110};
    case Tone::Info:
        break;
    }
    return kText;
}

// The seat drawn at the bottom of the window: ours, or seat 0 for a spectator.
int seat_at_bottom(const MatchView& v) {
    return v.you >= 0 ? v.you : 0;
}

std::string queen_text(const MatchModel& model) {
    const proto::QueenInfo& q = model.view().queen;
    switch (q.state) {
    case proto::QueenState::Pending:
        return "Queen: " + model.seat_name(q.seat) + " must cover";
    case proto::QueenState::Covered:
        return "Queen: covered by " + model.seat_name(q.seat);
    case proto::QueenState::None:
        return "No queen in this game";
    case proto::QueenState::OnBoard:
        break;
    }
    return "Queen: on the board";
}

} // namespace

void HudPainter::draw(sf::RenderTarget& target, Blitter& blitter, const ScreenLayout& layout,
                      const MatchModel& model, const ConnectionLine& connection, double local_s,
                      double side_taken, double bar_taken, const Sketch& bar_buttons) {
    top_.draw(target, blitter, texts_, layout.top_bar, kBar,
              top_bar(layout.top_bar, model, local_s));
    if (layout.seat_bar.h > 0.0) {
        seat_.draw(target, blitter, texts_, layout.seat_bar, kBar,
                   seat_bar(layout.seat_bar, model, local_s));
    }
    Sketch bottom = bottom_bar(layout.bottom_bar, model, connection, bar_taken);
    bottom.items.insert(bottom.items.end(), bar_buttons.items.begin(), bar_buttons.items.end());
    bottom_.draw(target, blitter, texts_, layout.bottom_bar, kBar, bottom);
    Sketch over_board;
    const Rect& side = layout.side;
    const double gap = side_taken > 0.0 ? 6.0 : 0.0;
    sketch_messages(
        over_board,
        {side.x, side.y + side_taken + gap, side.w, std::max(side.h - side_taken - gap, 0.0)},
        model, local_s);
    sketch_room_code(over_board, layout.board, model);
    over_board_.draw_overlay(target, blitter, texts_, over_board);
}

Sketch HudPainter::top_bar(const Rect& top, const MatchModel& model, double local_s) {
    Sketch s;
    if (model.view().seats.size() == 4) {
        // The seats at the left, across and right of the turned board (seat order runs
        // anticlockwise on the screen: ours + 1 is at the right, + 2 across, + 3 at the left).
        const int base = seat_at_bottom(model.view());
        const double side_w = std::round(top.w * 0.3);
        sketch_seat(s, {top.x, top.y, side_w, top.h}, model, (base + 3) % 4, false);
        sketch_seat(s, {top.x + side_w, top.y, top.w - 2.0 * side_w, top.h}, model, (base + 2) % 4,
                    false);
        sketch_seat(s, {top.x + top.w - side_w, top.y, side_w, top.h}, model, (base + 1) % 4, true);
        return s;
    }
    const double side_w = std::round(top.w * 0.34);
    // Our seat on the left (a spectator sees seat 0 there).
    const int left_seat = model.view().you >= 0 ? model.view().you : 0;
    sketch_seat(s, {top.x, top.y, side_w, top.h}, model, left_seat, false);
    sketch_seat(s, {top.x + top.w - side_w, top.y, side_w, top.h}, model, 1 - left_seat, true);
    sketch_centre(s, {top.x + side_w, top.y, top.w - 2.0 * side_w, top.h}, model, local_s);
    return s;
}

Sketch HudPainter::seat_bar(const Rect& area, const MatchModel& model, double local_s) {
    Sketch s;
    const double side_w = std::round(area.w * 0.3);
    const Rect left{area.x, area.y, side_w, area.h};
    const Rect right{area.x + area.w - side_w, area.y, side_w, area.h};
    sketch_seat(s, {area.x + side_w, area.y, area.w - 2.0 * side_w, area.h}, model,
                seat_at_bottom(model.view()), false);
    const float mid = static_cast<float>(area.y + area.h / 2.0);
    sketch_status(s, left, model, local_s, mid);
    // Two lines ("Queen:" over the rest): a third of the bar is too narrow for a name on one.
    const std::string queen = queen_text(model);
    const std::size_t colon = queen.find(": ");
    const float x = static_cast<float>(right.x + right.w / 2.0);
    const float step = static_cast<float>(area.h * 0.2);
    if (colon == std::string::npos) {
        s.text(queen, text_size(area.h, 0.22), x, mid, kDim, Align::Centre);
    } else {
        s.text(queen.substr(0, colon + 1), text_size(area.h, 0.22), x, mid - step, kDim,
               Align::Centre);
        s.text(queen.substr(colon + 2), text_size(area.h, 0.22), x, mid + step, kDim,
               Align::Centre);
    }
    return s;
}

void HudPainter::sketch_seat(Sketch& sk, const Rect& area, const MatchModel& model, int seat,
                             bool right) {
    const MatchView& v = model.view();
    if (seat < 0 || static_cast<std::size_t>(seat) >= v.seats.size()) {
        return;
    }
    const SeatView& s = v.seats[static_cast<std::size_t>(seat)];
    const bool to_play = v.phase == proto::Phase::Aiming && v.to_play == seat;
    const Rect inner{area.x + 6.0, area.y + 5.0, area.w - 12.0, area.h - 10.0};
    sk.panel(inner, to_play ? sf::Color(92, 60, 28) : sf::Color(52, 34, 22),
             to_play ? kGold : sf::Color(80, 56, 40), to_play ? 2.0f : 1.0f);
    const float mid = static_cast<float>(inner.y + inner.h / 2.0);
    const double coin_r = inner.h * 0.26;
    const double pad = inner.h * 0.25;
    const double coin_x = right ? inner.x + inner.w - pad - coin_r : inner.x + pad + coin_r;
    const BodyKind kind = s.colour == proto::Colour::White   ? BodyKind::White
                          : s.colour == proto::Colour::Black ? BodyKind::Black
                                                             : BodyKind::Striker;
    const PieceLook look = piece_look(kind);
    if (s.colour != proto::Colour::None) { // freestyle: no colours, no dot
        sk.disc({coin_x, mid}, coin_r, look.rim);
        sk.disc({coin_x, mid}, coin_r * 0.85, look.fill);
    }
    const unsigned name_size = text_size(inner.h, 0.34);
    const unsigned score_size = text_size(inner.h, 0.62);
    std::string name = s.occupied ? s.name : "Free seat";
    if (const auto index = static_cast<std::size_t>(seat);
        s.occupied && index < seat_ratings_.size() && !seat_ratings_[index].empty()) {
        name += " " + seat_ratings_[index]; // beside the name: "Asha 1520?"
    }
    if (s.occupied && !s.connected) {
        name += " (away)";
    }
    if (seat == v.you) {
        name += " (you)";
    } else if (v.you >= 0 && seat == partner_of(v, v.you)) {
        name += " (partner)";
    }
    // The colour, and while the seat plays: what it has left to pocket.
    std::string sub = colour_word(s.colour);
    if (const auto coins = model.coins_left(seat); coins && s.occupied) {
        sub = coins_left_text(*coins);
    }
    if (s.dues > 0) {
        sub +=
            (sub.empty() ? "" : ", ") + std::string("owes ") + count_words(s.dues, "due", "dues");
    }
    const float text_x = static_cast<float>(right ? coin_x - coin_r - pad : coin_x + coin_r + pad);
    const Align align = right ? Align::Right : Align::Left;
    const float name_y = sub.empty() ? mid : mid - static_cast<float>(inner.h * 0.16);
    // The name and the line below it stay between the coin and the score (a long name shrinks,
    // then ends in "...").
    const std::string score = std::to_string(s.score);
    const double text_w = inner.w - (2.0 * coin_r + 3.0 * pad) -
                          static_cast<double>(texts_.width(score, score_size)) - pad;
    const FittedText name_fit = fitted(name, name_size, text_w);
    sk.text(name_fit.text, name_fit.size, text_x, name_y, kText, align);
    if (!sub.empty()) {
        const FittedText sub_fit = fitted(sub, text_size(inner.h, 0.26), text_w);
        sk.text(sub_fit.text, sub_fit.size, text_x, mid + static_cast<float>(inner.h * 0.22),
                s.dues > 0 ? kAlert : kDim, align);
    }
    const float score_x = static_cast<float>(right ? inner.x + pad : inner.x + inner.w - pad);
    sk.text(score, score_size, score_x, mid, to_play ? kGold : kText,
            right ? Align::Left : Align::Right);
}

void HudPainter::sketch_centre(Sketch& sk, const Rect& area, const MatchModel& model,
                               double local_s) {
    const float mid = static_cast<float>(area.y + area.h / 2.0);
    sketch_status(sk, area, model, local_s, mid - static_cast<float>(area.h * 0.14));
    sk.text(queen_text(model), text_size(area.h, 0.24), static_cast<float>(area.x + area.w / 2.0),
            mid + static_cast<float>(area.h * 0.26), kDim, Align::Centre);
}

void HudPainter::sketch_status(Sketch& sk, const Rect& area, const MatchModel& model,
                               double local_s, float y) {
    const MatchView& v = model.view();
    const float cx = static_cast<float>(area.x + area.w / 2.0);
    std::string status;
    sf::Color colour = kText;
    switch (v.phase) {
    case proto::Phase::Waiting: {
        const auto empty = std::count_if(v.seats.begin(), v.seats.end(),
                                         [](const SeatView& s) { return !s.occupied; });
        status = empty > 1
                     ? "Waiting for " + count_words(static_cast<int>(empty), "player", "players")
                     : std::string("Waiting for a player");
        break;
    }
    case proto::Phase::Moving:
        status = model.seat_name(v.to_play) + " shot";
        break;
    case proto::Phase::Aiming:
        status = model.my_turn() ? "Your turn" : model.seat_name(v.to_play) + " to play";
        colour = model.my_turn() ? kGold : kText;
        break;
    case proto::Phase::BoardOver:
        status = "Board " + std::to_string(v.board_number) + " over";
        break;
    case proto::Phase::GameOver:
        status = v.winner < 0                         ? "Game drawn"
                 : v.winner == team_of(v, v.you)      ? "You won!"
                 : team_seats(v, v.winner).size() > 1 ? team_name(v, v.winner) + " won"
                                                      : player_name_at_end(v, v.winner) + " won";
        colour = kGold;
        break;
    }
    if (const auto left = model.shot_clock_left_s(local_s)) {
        const int secs = static_cast<int>(std::ceil(*left));
        const bool hurry = *left <= MatchModel::kCountdownS;
        status += "  " + std::to_string(secs) + (hurry && model.my_turn() ? " s left!" : " s");
        if (hurry) {
            colour = kAlert;
        }
    }
    // Within its area, a few px from each edge (a long bot name shrinks, then ends in "...").
    const FittedText fit = fitted(status, text_size(area.h, 0.34), area.w - 16.0);
    sk.text(fit.text, fit.size, cx, y, colour, Align::Centre);
}

const FittedText& HudPainter::fitted(const std::string& text, unsigned size, double width) {
    if (fitted_.size() > 64) {
        fitted_.clear();
    }
    const auto key = std::make_tuple(text, size, std::lround(width));
    auto it = fitted_.find(key);
    if (it == fitted_.end()) {
        const unsigned min_size = std::max(10u, size * 3 / 4);
        it = fitted_
                 .emplace(key, texts_.fit(text, size, std::min(size, min_size),
                                          static_cast<float>(std::max(0.0, width))))
                 .first;
    }
    return it->second;
}

Sketch HudPainter::bottom_bar(const Rect& area, const MatchModel& model,
                              const ConnectionLine& connection, double bar_taken) {
    Sketch sk;
    const MatchView& v = model.view();
    const float mid = static_cast<float>(area.y + area.h / 2.0);
    // Smaller beside the buttons, so that the room, the rule set and the link fit one line.
    const unsigned size = text_size(area.h, bar_taken > 0.0 ? 0.4 : 0.48);
    // A replay's status line is long (turn, speed, the end's reason): its room line names the
    // rule set and the board only.
    std::string left = connection.replay
                           ? rule_set_name(v.rule_set)
                           : "Room " + v.code + "  \xc2\xb7  " + rule_set_name(v.rule_set) + " " +
                                 target_words(v.rule_set, v.options.target_points);
    left += "  \xc2\xb7  Board " + std::to_string(v.board_number);
    if (v.spectators > 0) {
        left += "  \xc2\xb7  " + count_words(v.spectators, "spectator", "spectators");
    }
    if (v.you < 0 && !connection.replay) {
        left += "  \xc2\xb7  spectating";
    }
    std::string right = connection.text;
    // The round trip only where the line has room for it (the buttons take the bar's right).
    if (connection.rtt_ms) {
        std::ostringstream rtt;
        rtt << "  \xc2\xb7  RTT " << static_cast<int>(std::lround(*connection.rtt_ms)) << " ms";
        const double room = area.w - bar_taken - 40.0;
        if (static_cast<double>(texts_.width(left, size) + texts_.width(right + rtt.str(), size)) <
            room) {
            right += rtt.str();
        }
    }
    // The room line keeps clear of the connection (it shrinks, then ends in "...").
    const double left_w =
        area.w - bar_taken - 40.0 - static_cast<double>(texts_.width(right, size));
    const FittedText left_fit = fitted(left, size, left_w);
    sk.text(left_fit.text, left_fit.size, static_cast<float>(area.x + 10.0), mid, kDim);
    sk.text(right, size, static_cast<float>(area.x + area.w - 10.0 - bar_taken), mid,
            connection.healthy ? kOk : kAlert, Align::Right);
    return sk;
}

void HudPainter::sketch_messages(Sketch& sk, const Rect& side, const MatchModel& model,
                                 double local_s) {
    messages_.clear();
    if (side.w <= 0.0 || side.h <= 0.0) {
        return;
    }
    const std::vector<HudLine> lines = model.log().visible(local_s);
    const double line_h = 20.0;
    const unsigned size = 14;
    const double pad = 8.0;
    // Newest last, at the bottom of the list; the list starts at the top of the side area and
    // the oldest lines leave at its top when it is full.
    std::vector<std::pair<std::vector<std::string>, Tone>> wrapped;
    double total = 0.0;
    for (const HudLine& line : lines) {
        wrapped.emplace_back(this->wrapped(line.text, size, side.w - 2.0 * pad), line.tone);
        total += static_cast<double>(wrapped.back().first.size()) * line_h + 4.0;
    }
    double y = side.y + std::min(0.0, side.h - total);
    for (std::size_t i = 0; i < wrapped.size(); ++i) {
        const auto& [rows, tone] = wrapped[i];
        const double h = static_cast<double>(rows.size()) * line_h;
        if (y >= side.y - 0.5) {
            const Rect r{side.x, std::round(y), side.w, h};
            sk.panel(r, sf::Color(52, 34, 22, 235));
            messages_.emplace_back(lines[i].text, r);
            double row_y = y;
            for (const std::string& row : rows) {
                sk.text(row, size, static_cast<float>(side.x + pad),
                        static_cast<float>(row_y + line_h / 2.0), tone_colour(tone));
                row_y += line_h;
            }
        }
        y += h + 4.0;
    }
}

const std::vector<std::string>& HudPainter::wrapped(const std::string& text, unsigned size,
                                                    double width) {
    if (width != wrapped_width_ || wrapped_.size() > 64) {
        wrapped_.clear();
        wrapped_width_ = width;
    }
    auto it = wrapped_.find(text);
    if (it == wrapped_.end()) {
        it = wrapped_.emplace(text, wrap_text(texts_, text, size, width)).first;
    }
    return it->second;
}

void HudPainter::sketch_room_code(Sketch& sk, const Rect& board, const MatchModel& model) const {
    const MatchView& v = model.view();
    if (v.phase != proto::Phase::Waiting || v.code.empty()) {
        return;
    }
    const Rect panel{board.x + board.w * 0.18, board.y + board.h * 0.36, board.w * 0.64,
                     board.h * 0.28};
    sk.panel(panel, sf::Color(20, 12, 8, 215), kGold, 2.0f);
    const float cx = static_cast<float>(panel.x + panel.w / 2.0);
    sk.text("Room code", text_size(panel.h, 0.1), cx, static_cast<float>(panel.y + panel.h * 0.17),
            kDim, Align::Centre);
    sk.text(v.code, text_size(panel.h, 0.34), cx, static_cast<float>(panel.y + panel.h * 0.5),
            kGold, Align::Centre);
    sk.text(v.seats.size() > 2 ? "Share it: the other players join with this code"
                               : "Share it: your opponent joins with this code",
            text_size(panel.h, 0.085), cx, static_cast<float>(panel.y + panel.h * 0.83), kText,
            Align::Centre);
}

} // namespace carrom::client::app
