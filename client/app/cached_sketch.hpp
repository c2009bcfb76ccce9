#pragma once
// A panel's sketch kept with what it was made from (the board's place and size, the panel's
// text): made again only when one of them changes.

#include "carrom/client/screen_mapping.hpp"
#include "sketch.hpp"

#include <optional>

namespace carrom::client::app {

template <class Text> class CachedSketch {
public:
    // The sketch of `text` over `board`, from make(board, text) when either differs from the last.
    template <class Make> const Sketch& get(const Rect& board, const Text& text, Make make) {
        if (!text_ || board != board_ || *text_ != text) {
            sketch_ = make(board, text);
            board_ = board;
            text_ = text;
        }
        return sketch_;
    }

private:
    Sketch sketch_;
    Rect board_;
    std::optional<Text> text_;
};

} // namespace carrom::client::app
