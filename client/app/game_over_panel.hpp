#pragma once
// The panel over the board once the game is over: who won and why, the final score, and what
// next: a rematch (the button, or R) or back to the lobby (the button, L or Escape). A spectator
// gets the lobby button only. Painted through a cached layer (it changes only when its text does).

#include "blitter.hpp"
#include "cached_layer.hpp"
#include "cached_sketch.hpp"
#include "carrom/client/game_over_text.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "sketch.hpp"
#include "text.hpp"

#include <SFML/Graphics.hpp>

#include <optional>
#include <vector>

namespace carrom::client::app {

class GameOverPanel {
public:
    enum class Choice { Rematch, Lobby };

    // Draws the panel centred on `board`.
    void draw(sf::RenderTarget& target, Blitter& blitter, TextCache& texts, const Rect& board,
              const GameOverText& text);
    // A key or a click on a button of the panel as last drawn.
    std::optional<Choice> on_event(const sf::Event& event, const GameOverText& text) const;

private:
    Sketch sketch(TextCache& texts, const Rect& board, const GameOverText& text);

    CachedLayer layer_;
    CachedSketch<GameOverText> sketch_;  // made again only when the board or the text changes
    std::optional<Rect> rematch_button_; // as last drawn; none while it cannot be pressed
    std::optional<Rect> lobby_button_;
};

// Splits `text` at spaces into as few lines no wider than `width` window px as it can (a word
// longer than that gets a line of its own), then evens them out: the lines are as narrow as they
// can be without needing one more.
std::vector<std::string> wrap_text(TextCache& texts, const std::string& text, unsigned size,
                                   double width);

} // namespace carrom::client::app
