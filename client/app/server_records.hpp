#pragma once
// What the desktop client reads from its server's HTTP API besides the game (docs/client.md,
// "Ratings, leaderboard and my matches"), fetched in the background (ApiFetcher) and picked up by
// update() each frame: the player's and the seats' ratings (RatingBook), the leaderboard, the
// player's last matches and a match's journal to replay. Reads are bounded: the player's own
// record on each return to the lobby (and once more 1.5 s later, as the web page does: a
// forfeit's result may still be on its way to the store); each identified-looking seat (not a
// bot) once when it appears in the room and once 1 s after its game is over. A read of a player
// that fails (503 store_busy, 429, no answer) is made once more 1 s later.

#include "api_fetcher.hpp"
#include "carrom/client/match_view.hpp"
#include "carrom/client/player_record.hpp"
#include "carrom/client/rating_book.hpp"
#include "carrom/client/replay_model.hpp"

#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

namespace carrom::client::app {

class ServerRecords {
public:
    // A list's state: not asked, being read (monostate), read, or the sentence why not.
    template <class T> using Reading = std::variant<std::monostate, T, std::string>;

    ServerRecords(const std::string& ws_url, const std::string& ca_file) : api_(ws_url, ca_file) {}

    // The lobby is shown for the player `name`.
    void lobby_entered(const std::string& name, double now);
    // Each frame in a room: reads the seats' ratings when they appear and after the game.
    void room_seen(const MatchView& view, double now);
    // The room is left: its seats' reads are forgotten (their ratings stay in the book).
    void room_left();
    void read_leaderboard(proto::RuleSet rule_set);
    void read_matches(const std::string& name);
    // Reads the journal at path (a match's "replay", /matches/ID) for a replay.
    void read_journal(const std::string& path);
    // Starts due reads and takes the answers that came.
    void update(double now);

    const RatingBook& book() const { return book_; }
    // Each seat's last player in this room (not a bot; "" for none yet): who played the game
    // also after they left the room.
    const std::vector<std::string>& seat_players() const { return seat_players_; }
    const Reading<Leaderboard>& leaderboard() const { return leaderboard_; }
    const Reading<PlayerRecord>& matches() const { return matches_; }
    const Reading<bool>& journal_state() const { return journal_state_; }
    // The journal read for a replay, once.
    std::optional<ReplayModel> take_journal() { return std::exchange(journal_, std::nullopt); }

private:
    void read_player(const std::string& name, const std::string& why);
    void take(const ApiFetcher::Done& done);
    double retry_at() const { return now_ + 1.0; }

    ApiFetcher api_;
    RatingBook book_;
    std::string lobby_name_;
    double lobby_reread_at_ = -1.0;         // < 0: none due
    std::set<std::string> room_names_read_; // seats read since they appeared in this room
    bool game_over_seen_ = false;           // the room's game over was handled
    double seats_reread_at_ = -1.0;         // < 0: none due
    std::vector<std::string> game_names_;   // the seats' names of the game being played
    std::vector<std::string> seat_players_;
    // Failed reads of a player, read once more: when (s), the name, the key's reason.
    std::vector<std::tuple<double, std::string, std::string>> retries_;
    double now_ = 0.0; // the time update() was last called with
    std::string matches_name_;
    std::string leaderboard_rule_set_; // the rule set asked for last ("icf", ...)
    Reading<Leaderboard> leaderboard_;
    Reading<PlayerRecord> matches_;
    Reading<bool> journal_state_;
    std::optional<ReplayModel> journal_;
};

} // namespace carrom::client::app
