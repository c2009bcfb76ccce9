#pragma once
// A rectangle of the window painted into a texture only when what it shows changes, and put on
// the window every frame by the Blitter. Under a software renderer this turns a dozen text draws
// a frame into one rectangle copy. Two kinds:
// - opaque (a HUD bar): covers its area with a background colour and the sketch;
// - overlay (messages over the board): transparent where the sketch draws nothing; its area is
//   the bounding box of the sketch's panels and discs (texts must sit on them).

#include "blitter.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "sketch.hpp"

#include <SFML/Graphics.hpp>

#include <memory>
#include <optional>

namespace carrom::client::app {

class CachedLayer {
public:
    // Opaque: covers `area` (whole window px) with `background`, then `sketch` (window px).
    void draw(sf::RenderTarget& target, Blitter& blitter, TextCache& texts, const Rect& area,
              sf::Color background, const Sketch& sketch);
    // Overlay: blends `sketch` over what is drawn already. An empty sketch draws nothing.
    void draw_overlay(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                      const Sketch& sketch);
    // How often the texture was painted (for the benchmark and tests of the caching).
    long repaints() const { return repaints_; }
    // Where the last draw_overlay drew (whole window px); nothing if its sketch was empty.
    const std::optional<Rect>& last_overlay() const { return last_overlay_; }

private:
    bool up_to_date(const Rect& area, sf::Color background, const Sketch& sketch) const;
    bool repaint(sf::RenderTarget& target, Blitter& blitter, TextCache& texts, const Rect& area,
                 sf::Color background, const Sketch& sketch);

    std::unique_ptr<sf::RenderTexture> canvas_; // painted here, then uploaded to texture_
    sf::Texture texture_;
    sf::VertexArray rect_{sf::Triangles};
    Rect area_;
    sf::Color background_;
    Sketch painted_;
    bool valid_ = false;
    long repaints_ = 0;
    std::optional<Rect> last_overlay_;
};

// The smallest whole-pixel rect holding every panel (with its outline) and disc of `sketch`,
// clipped to `bounds`; w = h = 0 if there are none.
Rect sketch_bounds(const Sketch& sketch, const Rect& bounds);

} // namespace carrom::client::app
