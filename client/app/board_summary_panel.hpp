#pragma once
// The card over the board between two boards (MatchModel::board_summary_shown): who won the
// board, its points and the score, the player's colour on the next board. A click or a key
// dismisses it; it also goes by itself (MatchModel::kBoardSummaryS). Painted through a cached
// layer (it changes only when its text does).

#include "blitter.hpp"
#include "cached_layer.hpp"
#include "cached_sketch.hpp"
#include "carrom/client/board_summary_text.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "sketch.hpp"
#include "text.hpp"

#include <SFML/Graphics.hpp>

namespace carrom::client::app {

class BoardSummaryPanel {
public:
    // Draws the card centred on `board`.
    void draw(sf::RenderTarget& target, Blitter& blitter, TextCache& texts, const Rect& board,
              const BoardSummaryText& text);
    // True for the events that dismiss the card: a key, a left click.
    static bool dismisses(const sf::Event& event);

private:
    Sketch sketch(const Rect& board, const BoardSummaryText& text) const;

    CachedLayer layer_;
    CachedSketch<BoardSummaryText> sketch_;
};

} // namespace carrom::client::app
