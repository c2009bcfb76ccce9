#pragma once
// What the desktop client adds around a match and the lobby: the buttons at the right of the
// bottom bar (Rules, Settings, Sound, Leave; keys H or F1, M, L), the question before leaving a
// running game ("Leave and forfeit?": Stay with Escape or N, Leave with Enter or Y), the rules
// screen per rule set, the settings (volume, mute, reduced motion; kept in the settings file,
// settings_file.hpp) and the first-game tips in the side area (Next, Skip).

#include "carrom/client/settings_file.hpp"
#include "carrom/proto/types.hpp"
#include "dialog_panel.hpp"
#include "text.hpp"

#include <SFML/Graphics.hpp>

#include <string>
#include <vector>

namespace carrom::client::app {

class MatchMenus {
public:
    enum class Open { None, Leave, Rules, Settings };
    struct Outcome {
        bool used = false;       // the event was for the menus: nothing else handles it
        bool want_leave = false; // Leave (button or L): the window asks first if the game runs
        bool leave = false;      // Leave confirmed
    };

    // `path` empty: the settings are not kept.
    MatchMenus(std::string path, SettingsLoad loaded);

    // in_room: the bottom bar's buttons and the match keys apply, Rules opening at the room's
    // `rule_set`; in the lobby F1 opens the rules (letters go to the lobby's fields).
    Outcome on_event(const sf::Event& event, bool in_room, proto::RuleSet rule_set);
    void ask_leave(std::string consequence);
    void open_rules(proto::RuleSet rule_set);
    void open_settings() { open_ = Open::Settings; }
    void close() { open_ = Open::None; }
    Open open() const { return open_; }

    // Lays out the bottom bar's buttons (right-aligned in `bar`); returns their total width.
    double layout_bar(TextCache& texts, const Rect& bar);
    // The buttons as laid out, for the bottom bar's sketch (the HUD paints them with the bar).
    void sketch_bar(Sketch& sketch) const;
    // The open dialog: the question over the board, the rules and settings over `band` (the
    // window between the bars).
    void draw_dialog(sf::RenderTarget& target, Blitter& blitter, TextCache& texts,
                     const Rect& board, const Rect& band);
    // The tips card at the top of `side` while `playing` and not yet seen; its height (0: none).
    double draw_tips(sf::RenderTarget& target, Blitter& blitter, TextCache& texts, const Rect& side,
                     bool playing, proto::RuleSet rule_set);

    const Settings& settings() const { return settings_; }
    const std::string& settings_problem() const { return problem_; }
    // Report fields for tests: the open dialog's name, the tip shown, the bar's button rects.
    std::string open_name() const;
    int tip_step() const { return tips_shown_ ? tip_step_ : -1; }
    int rules_tab() const { return rules_tab_; }
    const std::vector<Rect>& bar_buttons() const { return bar_; }
    const std::vector<Rect>& dialog_buttons() const { return dialog_.buttons(); }
    const std::vector<Rect>& tips_buttons() const { return tips_.buttons(); }
    const std::string& leave_consequence() const { return leave_consequence_; }

private:
    void change(const Settings& next);
    Outcome dialog_event(const sf::Event& event);

    std::string path_;
    Settings settings_;
    std::string problem_;
    Open open_ = Open::None;
    int rules_tab_ = 0; // proto::RuleSet as an index
    int tip_step_ = 0;
    bool tips_shown_ = false; // drawn in the last frame
    std::string leave_consequence_;
    DialogPanel dialog_;
    DialogPanel tips_;
    std::vector<Rect> bar_; // Rules, Settings, Sound, Leave as laid out
};

} // namespace carrom::client::app
