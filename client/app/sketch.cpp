#include "sketch.hpp"

#include "draw_util.hpp"

#include <tuple>

namespace carrom::client::app {
namespace {

struct ItemPainter {
    sf::RenderTarget& target;
    TextCache& texts;

    void operator()(const SketchPanel& p) const {
        draw_panel(target, p.rect, p.fill, p.outline, p.outline_px);
    }
    void operator()(const SketchDisc& d) const {
        sf::VertexArray tris(sf::Triangles);
        add_disc(tris, d.centre, d.r, d.colour);
        target.draw(tris);
    }
    void operator()(const SketchText& t) const {
        texts.draw(target, t.text, t.size, t.x, t.y_mid, t.colour, t.align);
    }
};

} // namespace

bool operator==(const SketchPanel& a, const SketchPanel& b) {
    return a.rect == b.rect && a.fill == b.fill && a.outline == b.outline &&
           a.outline_px == b.outline_px;
}

bool operator==(const SketchDisc& a, const SketchDisc& b) {
    return a.centre == b.centre && a.r == b.r && a.colour == b.colour;
}

bool operator==(const SketchText& a, const SketchText& b) {
    return std::tie(a.text, a.size, a.x, a.y_mid, a.align) ==
               std::tie(b.text, b.size, b.x, b.y_mid, b.align) &&
           a.colour == b.colour;
}

bool operator==(const Sketch& a, const Sketch& b) {
    return a.items == b.items;
}

void draw_sketch(sf::RenderTarget& target, TextCache& texts, const Sketch& sketch) {
    const ItemPainter painter{target, texts};
    for (const SketchItem& item : sketch.items) {
        std::visit(painter, item);
    }
}

} // namespace carrom::client::app
