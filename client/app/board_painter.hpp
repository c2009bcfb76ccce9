#pragma once
// Draws the board as a player knows it: wooden frame and playing surface, four pockets,
// baselines with their end circles, the centre circles and the diagonal arrows, all scaled from
// the board geometry. The static board is painted once per size into a texture; the pieces are
// drawn every frame on top.

#include "blitter.hpp"
#include "carrom/client/board_geometry.hpp"
#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/screen_mapping.hpp"

#include <SFML/Graphics.hpp>

#include <optional>
#include <utility>

#include <memory>
#include <vector>

namespace carrom::client::app {

struct PieceLook {
    sf::Color fill;
    sf::Color rim;
    sf::Color ring;
};

PieceLook piece_look(BodyKind kind);

// Per frame the board and its margins cost one opaque rectangle copy and each resting piece
// one small premultiplied rectangle, cut from an atlas; both are painted once per window size
// with antialiasing and handed to the Blitter. Under a software renderer (Xvfb, llvmpipe) fill
// rate is what a frame costs, so nothing is drawn twice and nothing needs a per-pixel shader.
class BoardPainter {
public:
    explicit BoardPainter(const BoardGeometry& geometry) : geometry_(geometry) {}

    // Covers `band` (whole window px, the space between the HUD bars) with the board and the
    // margins beside it: every pixel of the band exactly once, so the window needs no clear.
    void draw_board(sf::RenderTarget& target, Blitter& blitter, const ScreenMapping& mapping,
                    const Rect& band);
    // Pieces at their rendered positions (falling ones shrink and fade).
    void draw_pieces(sf::RenderTarget& target, Blitter& blitter, const ScreenMapping& mapping,
                     const std::vector<RenderedBody>& bodies);
    // One striker, e.g. while aiming. `warning` (an illegal placement): the striker see-through
    // (kOverlapAlpha) with a red ring, so the piece under it shows, and `blocking`, the piece in
    // the way (its centre and radius, board px), outlined on top.
    void draw_striker(sf::RenderTarget& target, Blitter& blitter, const ScreenMapping& mapping,
                      Vec2 pos_px, double alpha, bool warning,
                      std::optional<std::pair<Vec2, double>> blocking = std::nullopt);
    static constexpr double kOverlapAlpha = 0.45;
    // How often the board band and the piece atlas were painted (once per window size).
    long repaints() const { return repaints_; }

    static inline const sf::Color kMargin{28, 18, 12};

private:
    bool repaint_band(sf::RenderTarget& target, Blitter& blitter, const ScreenMapping& mapping,
                      const Rect& band);
    bool repaint_atlas(sf::RenderTarget& target, Blitter& blitter, double scale);

    BoardGeometry geometry_;
    sf::Texture band_;
    Rect painted_band_;
    Vec2 painted_origin_;
    double painted_scale_ = 0.0;
    bool band_ok_ = false;
    // One cell per piece kind (BodyKind order), each a square of cell_px_ window px with the
    // piece (and its shadow) centred in it; colours premultiplied by alpha.
    sf::Texture atlas_;
    double atlas_scale_ = 0.0;
    double cell_px_ = 0.0;
    bool atlas_ok_ = false;
    sf::VertexArray resting_{sf::Triangles};
    sf::VertexArray falling_{sf::Triangles};
    sf::VertexArray overlay_{sf::Triangles};
    long repaints_ = 0;
};

} // namespace carrom::client::app
