#pragma once
// Which seat's quick reaction (the "emote" event) is on show, and the receiver's mutes: a muted
// seat's emotes are not shown; muting all covers seats that join later too. The words of each
// emote are the web page's (web/js/emotes.js). Times: the local clock, s.

#include "carrom/proto/types.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace carrom::client {

// "Nice shot!", "Good game!", ...
std::string emote_text(proto::Emote emote);

struct ShownEmote {
    int seat = 0;
    proto::Emote emote = proto::Emote::NiceShot;
    friend bool operator==(const ShownEmote&, const ShownEmote&) = default;
};

class EmoteBoard {
public:
    static constexpr double kShowS = 4.0; // an emote stays beside its seat this long

    // An emote from `seat` arrived at local_s; false when the seat is muted (nothing shows).
    bool receive(int seat, proto::Emote emote, double local_s);
    bool muted(int seat) const { return all_muted_ || muted_seats_.contains(seat); }
    // Muting hides what the seat shows now.
    void set_muted(int seat, bool muted);
    void set_all_muted(bool muted);
    bool all_muted() const { return all_muted_; }
    // The emotes on show at local_s, in seat order.
    std::vector<ShownEmote> visible(double local_s) const;
    int received() const { return received_; } // emotes received, shown or not
    // A new room: nothing on show; the mutes stay (they are the player's choice).
    void clear() { shown_.clear(); }

private:
    struct Shown {
        proto::Emote emote;
        double until_s;
    };
    std::map<int, Shown> shown_; // by seat
    std::set<int> muted_seats_;
    bool all_muted_ = false;
    int received_ = 0;
};

} // namespace carrom::client
