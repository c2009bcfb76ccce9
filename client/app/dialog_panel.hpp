#pragma once
// A card with a title, wrapped lines and a row (or rows) of buttons: the question before leaving
// a running game, the rules screen, the settings (over the board) and the first-game tips (at the
// top of the side area). Sketched again only when what it shows changes, painted through a
// cached layer; a click on a button as last drawn gives its index.

#include "blitter.hpp"
#include "cached_layer.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "sketch.hpp"
#include "text.hpp"

#include <SFML/Graphics.hpp>

#include <optional>
#include <string>
#include <vector>

namespace carrom::client::app {

struct Dialog {
    std::string title; // empty: none (the tips card)
    std::vector<std::string> lines;
    std::vector<std::string> buttons;
    int chosen = -1; // a button drawn as the chosen one (a rule set's tab), or -1
    bool operator==(const Dialog&) const = default;
};

class DialogPanel {
public:
    // Centred on `area` over a veil (a card over the board), or filling the width of `area` from
    // its top (at_top). Returns the card's height, window px.
    double draw(sf::RenderTarget& target, Blitter& blitter, TextCache& texts, const Rect& area,
                const Dialog& dialog, bool at_top);
    // The button under a left click, from the buttons as last drawn.
    std::optional<int> clicked(const sf::Event& event) const;
    void hide() {
        buttons_.clear();
        made_for_.reset();
    }
    const std::vector<Rect>& buttons() const { return buttons_; }

private:
    // The card's sketch and its buttons; returns the card's height.
    double sketch(TextCache& texts, const Rect& area, const Dialog& dialog, bool at_top);

    std::vector<Rect> buttons_; // as last drawn, one per Dialog::buttons entry
    CachedLayer layer_;
    Sketch sketch_;
    double card_h_ = 0.0;
    struct MadeFor {
        Rect area;
        Dialog dialog;
        bool at_top = false;
    };
    std::optional<MadeFor> made_for_; // what sketch_ shows
};

} // namespace carrom::client::app
