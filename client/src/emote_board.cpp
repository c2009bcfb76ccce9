#include "carrom/client/emote_board.hpp"

namespace carrom::client {

std::string emote_text(proto::Emote emote) {
    switch (emote) {
    case proto::Emote::NiceShot:
        return "Nice shot!";
    case proto::Emote::GoodGame:
        return "Good game!";
    case proto::Emote::WellPlayed:
        return "Well played!";
    case proto::Emote::Thanks:
        return "Thanks!";
    case proto::Emote::GoodLuck:
        return "Good luck!";
    case proto::Emote::Oops:
        return "Oops!";
    case proto::Emote::Wow:
        return "Wow!";
    case proto::Emote::Sorry:
        return "Sorry!";
    }
    return {};
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
