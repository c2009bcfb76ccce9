#pragma once
// Draws the board as a player knows it: wooden frame and playing surface, four pockets,
// baselines with their end circles, the centre circles and the diagonal arrows, all scaled from
// the board geometry. The static board is painted once per size into a texture; the pieces are
// drawn every frame on top.

#include "carrom/client/board_geometry.hpp"
#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/screen_mapping.hpp"

#include <SFML/Graphics.hpp>

#include <memory>
#include <vector>

namespace carrom::client::app {

struct PieceLook {
    sf::Color fill;
    sf::Color rim;
    sf::Color ring;
};

PieceLook piece_look(BodyKind kind);

class BoardPainter {
public:
    explicit BoardPainter(const BoardGeometry& geometry);

    // The static board for a square of side_px window px (repainted when the size changes).
    void draw_board(sf::RenderTarget& target, const ScreenMapping& mapping);
    // Pieces at their rendered positions (falling ones shrink and fade).
    void draw_pieces(sf::RenderTarget& target, const ScreenMapping& mapping,
                     const std::vector<RenderedBody>& bodies);
    // One striker, e.g. while aiming; `warning` draws it red (illegal placement).
    void draw_striker(sf::RenderTarget& target, const ScreenMapping& mapping, Vec2 pos_px,
                      double alpha, bool warning);

private:
    void repaint(unsigned side_px);
    void add_piece(sf::VertexArray& tris, const ScreenMapping& mapping, BodyKind kind, Vec2 pos,
                   double scale, double alpha) const;

    BoardGeometry geometry_;
    std::unique_ptr<sf::RenderTexture> texture_;
    unsigned painted_side_ = 0;
    sf::VertexArray pieces_;
};

} // namespace carrom::client::app
