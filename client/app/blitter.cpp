#include "blitter.hpp"

#include "draw_util.hpp"

#include <SFML/OpenGL.hpp>

#include <vector>

namespace carrom::client::app {
namespace {

// Outputs the texel as it is: llvmpipe recognises this shader as a blit.
constexpr const char* kFetchShader = "uniform sampler2D texture;\n"
                                     "void main() {\n"
                                     "    gl_FragColor = texture2D(texture, gl_TexCoord[0].xy);\n"
                                     "}\n";

std::vector<sf::Uint8> to_bgra(const sf::Image& image) {
    const sf::Vector2u size = image.getSize();
    const std::size_t n = static_cast<std::size_t>(size.x) * size.y;
    const sf::Uint8* rgba = image.getPixelsPtr();
    std::vector<sf::Uint8> bgra(4 * n);
    for (std::size_t i = 0; i < n; ++i) {
        bgra[4 * i + 0] = rgba[4 * i + 2];
        bgra[4 * i + 1] = rgba[4 * i + 1];
        bgra[4 * i + 2] = rgba[4 * i + 0];
        bgra[4 * i + 3] = rgba[4 * i + 3];
    }
    return bgra;
}

} // namespace

const sf::Shader* Blitter::shader() {
    if (!tried_shader_) {
        tried_shader_ = true;
        has_shader_ =
            sf::Shader::isAvailable() && shader_.loadFromMemory(kFetchShader, sf::Shader::Fragment);
        if (has_shader_) {
            shader_.setUniform("texture", sf::Shader::CurrentTexture);
        }
    }
    return has_shader_ ? &shader_ : nullptr;
}

bool Blitter::upload(sf::RenderTarget& target, sf::Texture& texture, const sf::Image& image) {
    const sf::Vector2u size = image.getSize();
    if (size.x == 0 || size.y == 0 || !texture.loadFromImage(image)) {
        return false;
    }
    texture.setSmooth(false);
    texture.setRepeated(false);
    if (!target.setActive(true)) {
        return true; // the RGBA copy SFML made is still right, only slower to draw
    }
    // Replace the texels with the same image in BGRA order, leaving SFML's binding as it was.
    const std::vector<sf::Uint8> bgra = to_bgra(image);
    GLint previous = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    glBindTexture(GL_TEXTURE_2D, texture.getNativeHandle());
    // Unsized GL_RGBA: Mesa then picks the texel format that matches the data, B8G8R8A8 (with
    // GL_RGBA8 it keeps R8G8B8A8 and converts, and the fast path is lost).
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, static_cast<GLsizei>(size.x),
                 static_cast<GLsizei>(size.y), 0, GL_BGRA, GL_UNSIGNED_BYTE, bgra.data());
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
    return true;
}

void Blitter::add_rect(sf::VertexArray& rects, const Rect& dst, const Rect& src, sf::Color colour) {
    const sf::Vertex tl{{f(dst.x), f(dst.y)}, colour, {f(src.x), f(src.y)}};
    const sf::Vertex tr{{f(dst.x + dst.w), f(dst.y)}, colour, {f(src.x + src.w), f(src.y)}};
    const sf::Vertex br{
        {f(dst.x + dst.w), f(dst.y + dst.h)}, colour, {f(src.x + src.w), f(src.y + src.h)}};
    const sf::Vertex bl{{f(dst.x), f(dst.y + dst.h)}, colour, {f(src.x), f(src.y + src.h)}};
    for (const sf::Vertex& v : {tl, tr, br, tl, br, bl}) {
        rects.append(v);
    }
}

void Blitter::copy(sf::RenderTarget& target, const sf::Texture& texture, float x, float y) {
    const sf::Vector2u size = texture.getSize();
    const Rect px{0.0, 0.0, static_cast<double>(size.x), static_cast<double>(size.y)};
    quad_.clear();
    add_rect(quad_, {static_cast<double>(x), static_cast<double>(y), px.w, px.h}, px);
    sf::RenderStates states(sf::BlendNone);
    states.texture = &texture;
    states.shader = shader();
    target.draw(quad_, states);
}

void Blitter::draw_premultiplied(sf::RenderTarget& target, const sf::VertexArray& rects,
                                 const sf::Texture& texture) {
    sf::RenderStates states(kPremultiplied);
    states.texture = &texture;
    states.shader = shader();
    target.draw(rects, states);
}

} // namespace carrom::client::app
