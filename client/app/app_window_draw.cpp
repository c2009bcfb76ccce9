#include "app_window.hpp"

#include "carrom/client/board_summary_text.hpp"
#include "carrom/client/emote_board.hpp"
#include "carrom/client/game_over_text.hpp"
#include "carrom/client/reconnect_text.hpp"
#include "draw_util.hpp"
#include "text.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace carrom::client::app {

void AppWindow::draw_aim_assist(sf::VertexArray& tris, const ScreenMapping& m) {
    const MatchView& v = model_.view();
    if (!v.aim_assist || !aim_.placement().legal) {
        return;
    }
    const ShotIntent shot = aim_.pending_shot();
    const std::vector<BodyState> board = model_.board_now();
    const auto contact =
        aim_assist_.guide(board, aim_.side(), Shot{shot.x_px, shot.angle_rad, shot.power});
    if (!contact) {
        return;
    }
    // The striker's path to the contact, its outline there, and the piece's direction: a line
    // from the piece's centre as long as the piece would roll freely (v / k), at most 200 px.
    const sf::Color guide(150, 230, 255, 200);
    const double w = std::max(m.length_to_screen(1.5), 1.0);
    add_line(tris, m.to_screen(aim_.striker_px()), m.to_screen(contact->striker_px), w, guide);
    add_arc(tris, m.to_screen(contact->striker_px), m.length_to_screen(physics_.striker_radius_px),
            w, 0.0, 2.0 * std::numbers::pi, guide, 40);
    const double roll_px = std::min(
        std::sqrt(length_squared(contact->piece_vel_px_s)) / physics_.damping_per_s, 200.0);
    const Vec2 end = contact->piece_px + contact->piece_direction * roll_px;
    add_line(tris, m.to_screen(contact->piece_px), m.to_screen(end),
             std::max(m.length_to_screen(2.5), 1.5), sf::Color(255, 210, 80, 230));
    add_disc(tris, m.to_screen(end), std::max(m.length_to_screen(3.0), 2.0),
             sf::Color(255, 210, 80, 230), 16);
}

void AppWindow::draw_emotes(double now) {
    const MatchView& v = model_.view();
    const ScreenMapping m = mapping();
    const Vec2 centre = physics_.centre();
    for (const ShownEmote& e : model_.emotes().visible(now)) {
        if (e.seat < 0 || static_cast<std::size_t>(e.seat) >= v.seats.size()) {
            continue;
        }
        // Just inside the seat's side of the board, towards its right-hand corner, clear of its
        // striker and of the pieces in the middle.
        const rules::Side side = model_.seat_side(e.seat);
        const Vec2 on_side = baseline_point(physics_, side, centre.x + 150.0);
        const Vec2 inward =
            (centre - on_side) * (1.0 / std::sqrt(length_squared(centre - on_side)));
        const Vec2 at = m.to_screen(on_side - inward * 40.0);
        const std::string text = seat_name(v, e.seat) + ": " + emote_text(e.emote);
        const auto size = static_cast<unsigned>(std::max(13.0, m.length_to_screen(13.0)));
        const double text_w = hud_.texts().width(text, size);
        const Rect box{at.x - text_w / 2.0 - 10.0, at.y - size * 0.9, text_w + 20.0, size * 1.8};
        draw_panel(window_, box, sf::Color(255, 244, 214, 235));
        hud_.texts().draw(window_, text, size, f(at.x), f(at.y), sf::Color(36, 22, 14),
                          Align::Centre);
    }
}

void AppWindow::draw_aim() {
    aim_striker_drawn_.reset();
    const ScreenMapping m = mapping();
    const MatchView& v = model_.view();
    if (aim_.phase() != AimPhase::Inactive) {
        const Vec2 s = aim_.striker_px();
        if (aim_.phase() == AimPhase::Pulling) {
            const ShotIntent shot = aim_.pending_shot();
            const double frac = aim_.power_fraction();
            sf::VertexArray tris(sf::Triangles);
            const Vec2 dir{std::cos(shot.angle_rad), std::sin(shot.angle_rad)};
            const double reach = 40.0 + 260.0 * frac;
            for (double d = physics_.striker_radius_px + 4.0; d < reach; d += 14.0) {
                add_line(tris, m.to_screen(s + dir * d),
                         m.to_screen(s + dir * std::min(d + 8.0, reach)),
                         std::max(m.length_to_screen(2.0), 1.5), sf::Color(255, 255, 255, 210));
            }
            add_line(tris, m.to_screen(s), m.to_screen(s - dir * (20.0 + 140.0 * frac)),
                     std::max(m.length_to_screen(1.0), 1.0), sf::Color(40, 20, 10, 150));
            const auto red = static_cast<sf::Uint8>(std::lround(60 + 195 * frac));
            const auto green = static_cast<sf::Uint8>(std::lround(210 - 150 * frac));
            add_arc(tris, m.to_screen(s), m.length_to_screen(physics_.striker_radius_px + 7.0),
                    m.length_to_screen(4.0), -std::numbers::pi / 2.0,
                    -std::numbers::pi / 2.0 + 2.0 * std::numbers::pi * frac,
                    sf::Color(red, green, 40), 48);
            draw_aim_assist(tris, m);
            window_.draw(tris);
            const Vec2 label = m.to_screen(s + Vec2{0.0, 0.0}) +
                               Vec2{0.0, -m.length_to_screen(physics_.striker_radius_px + 22.0)};
            hud_.texts().draw(window_, "Power " + std::to_string(std::lround(100.0 * frac)) + "%",
                              static_cast<unsigned>(std::max(12.0, m.length_to_screen(11.0))),
                              f(label.x), f(label.y), sf::Color::White, Align::Centre);
        }
        std::optional<std::pair<Vec2, double>> blocking;
        for (const RenderedBody& b : bodies_) {
            if (b.id == aim_.placement().blocking_id) {
                blocking = std::pair{b.pos_px, physics_.radius(b.kind)};
            }
        }
        board_painter_.draw_striker(window_, blitter_, m, s, 1.0, !aim_.placement().legal,
                                    blocking);
        aim_striker_drawn_ = s;
        if (!aim_.placement().legal) {
            const Vec2 label =
                m.to_screen(s) + Vec2{0.0, m.length_to_screen(physics_.striker_radius_px + 16.0)};
            hud_.texts().draw(window_, "Overlaps a piece",
                              static_cast<unsigned>(std::max(12.0, m.length_to_screen(10.0))),
                              f(label.x), f(label.y), sf::Color(255, 90, 80), Align::Centre);
        }
        return;
    }
    if (v.phase == proto::Phase::Aiming && !model_.animating() && v.to_play != v.you) {
        // The shooter's striker, where they are placing it on their baseline.
        const double x = v.aim_x_px.value_or(physics_.centre().x);
        const Vec2 s =
            baseline_point(physics_, model_.seat_side(v.to_play), clamp_baseline_x(physics_, x));
        board_painter_.draw_striker(window_, blitter_, m, s, 0.85, false);
        aim_striker_drawn_ = s;
    }
}

void AppWindow::draw_status_panel(const std::string& title, const std::string& detail) {
    const Rect& b = layout_.board;
    draw_panel(window_, b, sf::Color(20, 12, 8, 200));
    const float cx = f(b.x + b.w / 2.0);
    draw_text(window_, font_, title, static_cast<unsigned>(std::clamp(b.h * 0.05, 18.0, 44.0)), cx,
              f(b.y + b.h * 0.42), sf::Color(236, 184, 64), Align::Centre);
    // Each sentence from a new line, wrapped to the board's width, so long reasons (a refused
    // TLS certificate's) stay inside the window.
    const auto size = static_cast<unsigned>(std::clamp(b.h * 0.024, 12.0, 22.0));
    std::size_t start = 0;
    double y = b.y + b.h * 0.52;
    while (start < detail.size()) {
        std::size_t end = detail.find(". ", start);
        end = end == std::string::npos ? detail.size() : end + 1;
        for (const std::string& line :
             wrap_text(hud_.texts(), detail.substr(start, end - start), size, b.w * 0.9)) {
            draw_text(window_, font_, line, size, cx, f(y), sf::Color(242, 232, 214),
                      Align::Centre);
            y += size * 1.5;
        }
        start = end < detail.size() ? end + 1 : end;
    }
}

void AppWindow::draw(double now) {
    const ScreenMapping m = mapping();
    const SessionPhase phase = session_.phase();
    const Rect band{0.0, layout_.top_bar.h, layout_.top_bar.w,
                    layout_.seat_bar.y - layout_.top_bar.h};
    if (model_.view().in_room) {
        // The bars and the band between them cover the window: no clear.
        board_painter_.draw_board(window_, blitter_, m, band);
        board_painter_.draw_pieces(window_, blitter_, m, bodies_);
        draw_aim();
        const MatchView& v = model_.view();
        const bool playing =
            v.you >= 0 && (v.phase == proto::Phase::Aiming || v.phase == proto::Phase::Moving);
        const double tips_h =
            menus_.draw_tips(window_, blitter_, hud_.texts(), layout_.side, playing, v.rule_set);
        const double bar_w = menus_.layout_bar(hud_.texts(), layout_.bottom_bar);
        Sketch bar_buttons;
        menus_.sketch_bar(bar_buttons);
        // While the link is lost the card over the board has the details; the bar its title.
        const bool linked = phase == SessionPhase::InRoom || phase == SessionPhase::Joining;
        const ReconnectText card =
            reconnect_text(phase, session_.reconnect_info(now), session_.status_text());
        ConnectionLine line{linked ? session_.status_text() : card.title, linked,
                            session_.rtt_ms()};
        hud_.draw(window_, blitter_, layout_, model_, line, now, tips_h, bar_w, bar_buttons);
        draw_emotes(now);
        if (model_.view().phase == proto::Phase::GameOver) {
            game_over_.draw(window_, blitter_, hud_.texts(), layout_.board, game_over_words());
        }
        if (model_.board_summary_shown(now)) {
            board_summary_.draw(window_, blitter_, hud_.texts(), layout_.board,
                                board_summary_text(model_.view()));
        }
        if (phase == SessionPhase::Reconnecting || phase == SessionPhase::Failed ||
            phase == SessionPhase::Connecting || phase == SessionPhase::Greeting) {
            reconnect_panel_.draw(window_, hud_.texts(), layout_.board, card);
        }
        menus_.draw_dialog(window_, blitter_, hud_.texts(), layout_.board, band);
        return;
    }
    window_.clear(BoardPainter::kMargin);
    board_painter_.draw_board(window_, blitter_, m, band);
    std::string error;
    for (const HudLine& l : model_.log().visible(now)) {
        if (l.tone == Tone::Error) {
            error = l.text;
        }
    }
    switch (phase) {
    case SessionPhase::Lobby:
        draw_lobby(error, true);
        break;
    case SessionPhase::Joining:
        draw_lobby(error, false);
        break;
    case SessionPhase::Failed:
        draw_status_panel("Cannot connect", session_.status_text());
        break;
    default:
        draw_status_panel(options_.demo ? "Starting the demo" : "Connecting to " + options_.url,
                          session_.status_text());
        break;
    }
    menus_.draw_dialog(window_, blitter_, hud_.texts(), layout_.board, band);
}

} // namespace carrom::client::app
