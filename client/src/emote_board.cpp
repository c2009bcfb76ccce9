#include "carrom/client/emote_board.hpp"

#include <array>
#include <string_view>

namespace carrom::client {

namespace {

// The words of each emote, in proto::Emote's order (the web page's, web/js/emotes.js).
constexpr std::array<std::string_view, 8> kEmoteWords{
    "Nice shot!", "Good game!", "Well played!", "Thanks!", "Good luck!", "Oops!", "Wow!", "Sorry!"};
static_assert(kEmoteWords.size() == proto::kEmoteNames.size(), "words for every emote");

} // namespace

std::string emote_text(proto::Emote emote) {
    const auto index = static_cast<std::size_t>(emote);
    return index < kEmoteWords.size() ? std::string(kEmoteWords[index]) : std::string();
}

bool EmoteBoard::receive(int seat, proto::Emote emote, double local_s) {
    ++received_;
    if (muted(seat)) {
        return false;
    }
    shown_[seat] = Shown{emote, local_s + kShowS};
    return true;
}

void EmoteBoard::set_muted(int seat, bool muted) {
    if (muted) {
        muted_seats_.insert(seat);
        shown_.erase(seat);
    } else {
        muted_seats_.erase(seat);
    }
}

void EmoteBoard::set_all_muted(bool muted) {
    all_muted_ = muted;
    if (muted) {
        shown_.clear();
    }
}

std::vector<ShownEmote> EmoteBoard::visible(double local_s) const {
    std::vector<ShownEmote> out;
    for (const auto& [seat, shown] : shown_) {
        if (local_s < shown.until_s) {
            out.push_back({seat, shown.emote});
        }
    }
    return out;
}

} // namespace carrom::client
