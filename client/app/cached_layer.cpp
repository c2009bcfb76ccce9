#include "cached_layer.hpp"

#include "draw_util.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client::app {

Rect sketch_bounds(const Sketch& sketch, const Rect& bounds) {
    double x0 = bounds.x + bounds.w;
    double y0 = bounds.y + bounds.h;
    double x1 = bounds.x;
    double y1 = bounds.y;
    auto grow = [&](double left, double top, double right, double bottom) {
        x0 = std::min(x0, left);
        y0 = std::min(y0, top);
        x1 = std::max(x1, right);
        y1 = std::max(y1, bottom);
    };
    for (const SketchItem& item : sketch.items) {
        if (const auto* p = std::get_if<SketchPanel>(&item)) {
            const double o = std::max(0.0, static_cast<double>(p->outline_px));
            grow(p->rect.x - o, p->rect.y - o, p->rect.x + p->rect.w + o,
                 p->rect.y + p->rect.h + o);
        } else if (const auto* d = std::get_if<SketchDisc>(&item)) {
            grow(d->centre.x - d->r, d->centre.y - d->r, d->centre.x + d->r, d->centre.y + d->r);
        }
    }
    x0 = std::max(std::floor(x0), bounds.x);
    y0 = std::max(std::floor(y0), bounds.y);
    x1 = std::min(std::ceil(x1), bounds.x + bounds.w);
    y1 = std::min(std::ceil(y1), bounds.y + bounds.h);
    if (x1 <= x0 || y1 <= y0) {
        return {bounds.x, bounds.y, 0.0, 0.0};
    }
    return {x0, y0, x1 - x0, y1 - y0};
}

bool CachedLayer::up_to_date(const Rect& area, sf::Color background, const Sketch& sketch) const {
    return valid_ && area.x == area_.x && area.y == area_.y && area.w == area_.w &&
           area.h == area_.h && background == background_ && sketch == painted_;
}

bool CachedLayer::repaint(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                          const Rect& area, sf::Color background, const Sketch& sketch) {
    const auto w = static_cast<unsigned>(std::lround(area.w));
    const auto h = static_cast<unsigned>(std::lround(area.h));
    if (w == 0 || h == 0) {
        return false;
    }
    if (!canvas_ || canvas_->getSize() != sf::Vector2u(w, h)) {
        canvas_ = std::make_unique<sf::RenderTexture>();
        if (!canvas_->create(w, h)) {
            canvas_.reset();
            return false;
        }
    }
    canvas_->setView(sf::View(sf::FloatRect(f(area.x), f(area.y), f(w), f(h))));
    // Over a transparent background the usual alpha blend leaves premultiplied colours.
    canvas_->clear(background);
    draw_sketch(*canvas_, texts, sketch);
    canvas_->display();
    if (!blitter.upload(target, texture_, canvas_->getTexture().copyToImage())) {
        return false;
    }
    area_ = area;
    background_ = background;
    painted_ = sketch;
    ++repaints_;
    return true;
}

void CachedLayer::draw(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                       const Rect& area, sf::Color background, const Sketch& sketch) {
    if (!up_to_date(area, background, sketch)) {
        valid_ = repaint(target, blitter, texts, area, background, sketch);
    }
    if (!valid_) {
        draw_panel(target, area, background);
        draw_sketch(target, texts, sketch);
        return;
    }
    blitter.copy(target, texture_, f(area.x), f(area.y));
}

void CachedLayer::draw_overlay(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                               const Sketch& sketch) {
    last_overlay_.reset();
    if (sketch.items.empty()) {
        return;
    }
    const sf::Vector2f view = target.getView().getSize();
    const Rect area =
        sketch_bounds(sketch, {0.0, 0.0, static_cast<double>(view.x), static_cast<double>(view.y)});
    if (area.w <= 0.0 || area.h <= 0.0) {
        return;
    }
    last_overlay_ = area;
    if (!up_to_date(area, sf::Color::Transparent, sketch)) {
        valid_ = repaint(target, blitter, texts, area, sf::Color::Transparent, sketch);
    }
    if (!valid_) {
        draw_sketch(target, texts, sketch);
        return;
    }
    rect_.clear();
    Blitter::add_rect(rect_, area, {0.0, 0.0, area.w, area.h});
    blitter.draw_premultiplied(target, rect_, texture_);
}

} // namespace carrom::client::app
