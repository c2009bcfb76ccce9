#pragma once
// The HUD: seats with names, scores, dues and the coins each has left to pocket along the top;
// whose turn, the shot clock and the queen in the middle; room, rule set, connection and round trip
// along the bottom (up to the buttons at its right, match_menus.hpp); recent messages in the side
// area beside or under the board (never over it), newest last, below the first-game tips; the room
// code large while the room waits for a player. Doubles: the seats at the left, across and right of
// the turned board along the top, our own seat (the bottom one) in the seat bar below the board
// between the turn and the queen; the partner marked, partners showing their team's score.

#include "cached_layer.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "sketch.hpp"

#include <SFML/Graphics.hpp>

#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace carrom::client::app {

struct ConnectionLine {
    std::string text; // "Connected", "Reconnecting (attempt 2)..."
    bool healthy = true;
    std::optional<double> rtt_ms;
    bool replay = false; // a replay's: the room line says only the rule set and the board
};

// The bars are sketched every frame (cheap, plain data) but painted into their textures only
// when the sketch differs from the last one: the shot clock repaints the top bar once a second.
class HudPainter {
public:
    explicit HudPainter(const sf::Font& font) : texts_(font) {}
    // side_taken: the px at the top of layout.side the tips use; bar_taken: the px at the right of
    // the bottom bar its buttons use.
    void draw(sf::RenderTarget& target, Blitter& blitter, const ScreenLayout& layout,
              const MatchModel& model, const ConnectionLine& connection, double local_s,
              double side_taken = 0.0, double bar_taken = 0.0, const Sketch& bar_buttons = {});
    // How often the bars and the messages were painted into their textures.
    long bar_repaints() const {
        return top_.repaints() + seat_.repaints() + bottom_.repaints() + over_board_.repaints();
    }
    TextCache& texts() { return texts_; }
    // Each seat's rating shown beside its name ("1520?", "1532 (+14)"; "" for none), by seat.
    void set_seat_ratings(std::vector<std::string> ratings) { seat_ratings_ = std::move(ratings); }
    // The part of the window the last draw covered with messages or the room code, if any.
    const std::optional<Rect>& overlay_area() const { return over_board_.last_overlay(); }
    // Each message line as last drawn: its text and window px.
    const std::vector<std::pair<std::string, Rect>>& message_rects() const { return messages_; }

private:
    Sketch top_bar(const Rect& area, const MatchModel& model, double local_s);
    // Doubles: our seat with the turn and the queen beside it.
    Sketch seat_bar(const Rect& area, const MatchModel& model, double local_s);
    void sketch_seat(Sketch& s, const Rect& area, const MatchModel& model, int seat, bool right);
    void sketch_centre(Sketch& s, const Rect& area, const MatchModel& model, double local_s);
    void sketch_status(Sketch& s, const Rect& area, const MatchModel& model, double local_s,
                       float y);
    Sketch bottom_bar(const Rect& area, const MatchModel& model, const ConnectionLine& connection,
                      double bar_taken);
    // The message rows of `text` at `width` (wrapped once per text and width).
    const std::vector<std::string>& wrapped(const std::string& text, unsigned size, double width);
    // `text` made to fit `width` px (TextCache::fit, at least 3/4 of `size`), kept per text,
    // size and width.
    const FittedText& fitted(const std::string& text, unsigned size, double width);
    void sketch_messages(Sketch& s, const Rect& side, const MatchModel& model, double local_s);
    void sketch_room_code(Sketch& s, const Rect& board, const MatchModel& model) const;

    TextCache texts_;
    std::vector<std::string> seat_ratings_;
    CachedLayer top_;
    CachedLayer seat_;
    CachedLayer bottom_;
    CachedLayer over_board_;
    std::vector<std::pair<std::string, Rect>> messages_;
    std::map<std::string, std::vector<std::string>> wrapped_; // at wrapped_width_
    double wrapped_width_ = 0.0;
    std::map<std::tuple<std::string, unsigned, long>, FittedText> fitted_; // key width in px
};

} // namespace carrom::client::app
