#pragma once
// Copies cached images (the board, the HUD bars, the piece atlas) onto the window the way a
// software renderer does fastest. Mesa's llvmpipe (what Xvfb gives) runs a general per-pixel
// shader for SFML's usual textured draws (texture times vertex colour), about 4 ns a pixel: a
// 900 x 900 window is then 3 ms a frame before anything moves. It has a linear fast path, a
// row copy, when a rectangle is drawn with a shader that only fetches the texel, from a BGRA
// texture with nearest sampling, with blending off or premultiplied. The Blitter draws exactly
// that; on other drivers it is simply an ordinary textured draw.

#include "carrom/client/screen_mapping.hpp"

#include <SFML/Graphics.hpp>

namespace carrom::client::app {

class Blitter {
public:
    // Uploads `image` into `texture` with BGRA texel order, nearest sampling, clamped edges.
    // Needs `target` (any SFML target) to make a GL context current.
    bool upload(sf::RenderTarget& target, sf::Texture& texture, const sf::Image& image);
    // Copies the whole texture to target at whole window px (x, y), replacing what is there.
    void copy(sf::RenderTarget& target, const sf::Texture& texture, float x, float y);
    // Draws rectangles (6 vertices each in a Triangles array; colours ignored) cut from a
    // texture that holds premultiplied colours, blended over what is there.
    void draw_premultiplied(sf::RenderTarget& target, const sf::VertexArray& rects,
                            const sf::Texture& texture);
    // Appends one rectangle (two triangles) of window px `dst` showing texture px `src`.
    static void add_rect(sf::VertexArray& rects, const Rect& dst, const Rect& src,
                         sf::Color colour = sf::Color::White);

    static inline const sf::BlendMode kPremultiplied{sf::BlendMode::One,
                                                     sf::BlendMode::OneMinusSrcAlpha};

private:
    const sf::Shader* shader();

    sf::Shader shader_;
    bool tried_shader_ = false;
    bool has_shader_ = false;
    sf::VertexArray quad_{sf::Triangles};
};

} // namespace carrom::client::app
