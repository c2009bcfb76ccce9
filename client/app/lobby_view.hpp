#pragma once
// The in-window lobby, as the web page's: the player's name, the rule set and the server bot's
// level (each button steps to the next choice), singles or doubles, then create a room (alone or
// with server bots in the other seats), quick match, or type a room code to join as a player or
// to watch; How to play and Settings; the Leaderboard (also F2) and My matches (also F3). Also
// shows the connection status, the player's rating line ("Rating: ICF 1532 (+14)") and the last
// error. A click on the name or the code field chooses where typing goes (the code field at
// first).

#include "carrom/client/client_session.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "carrom/proto/types.hpp"

#include <SFML/Graphics.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace carrom::client::app {

class LobbyView {
public:
    enum class Menu { None, Rules, Settings, Leaderboard, Matches };

    LobbyView(const sf::Font& font, std::string name) : font_(font), name_(std::move(name)) {}

    // A button press or Enter in the code field gives a room request.
    std::optional<RoomRequest> on_event(const sf::Event& event, const Rect& area);
    // rating: the player's rating line ("" for none).
    void draw(sf::RenderTarget& target, const Rect& area, const std::string& status,
              const std::string& error, bool can_choose, const std::string& rating = "") const;
    // How to play, Settings, Leaderboard or My matches pressed since the last call.
    Menu take_menu() { return std::exchange(menu_, Menu::None); }
    const std::string& name() const { return name_; }
    proto::RuleSet rule_set() const { return rule_set_; }
    proto::BotLevel bot_level() const { return bot_level_; }
    // Every control's rect in `area` (name, rule set, bot level, singles, doubles, create, bot,
    // quick, code, join, watch, how to play, settings, leaderboard, my matches), for the
    // screenshot report.
    std::vector<Rect> control_rects(const Rect& area) const;

private:
    enum Control {
        kName,
        kRuleSet,
        kBotLevel,
        kSingles,
        kDoubles,
        kCreate,
        kBot,
        kQuick,
        kCode,
        kJoin,
        kWatch,
        kHelp,
        kSettings,
        kLeaderboard,
        kMatches,
        kControlCount
    };
    Rect control_rect(Control c, const Rect& area) const;
    std::optional<RoomRequest> press(Control c);
    std::string label(Control c) const;

    const sf::Font& font_;
    std::string name_;
    std::string code_;
    bool typing_name_ = false; // where typed text goes: the name or the room code
    int seats_ = 2;            // 2: singles, 4: doubles (for create, the bots and quick match)
    proto::RuleSet rule_set_ = proto::RuleSet::Icf;
    proto::BotLevel bot_level_ = proto::BotLevel::Medium;
    Menu menu_ = Menu::None;
};

} // namespace carrom::client::app
