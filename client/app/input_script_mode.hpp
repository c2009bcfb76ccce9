#pragma once
// carrom-client --input: keys and clicks handed to the window unattended, as a player would give
// them, one every kFramesApart frames, for tests of the menus. A token is a key ("a" to "z",
// "Escape", "Enter", "F1", "F2", "F3", "Tab") or a click on the centre of a button as last drawn:
// "bar:N" (the bottom bar's N-th button: 0 Rules, 1 Settings, 2 Sound, 3 Leave), "dialog:N" (the
// open dialog's), "tips:N" (the first-game tips'), "lobby:N" (the lobby's controls in
// LobbyView::control_rects order), "leaderboard:N", "matches:N" (the lobby's Leaderboard and My
// matches pages: AppWindow::ui_json), or "wait" (nothing, for kFramesApart frames). The script
// starts at the first frame showing our turn at rest in a room, or, when the run asks for no room,
// the connected lobby. While tokens remain, a screenshot waits (UnattendedFrame::input_pending). A
// click on a button not drawn is skipped.

#include "unattended_mode.hpp"

#include <string>
#include <vector>

namespace carrom::client::app {

class InputScriptMode final : public UnattendedMode {
public:
    InputScriptMode(std::vector<std::string> tokens, bool in_lobby)
        : tokens_(std::move(tokens)), in_lobby_(in_lobby) {}
    void on_frame(UnattendedFrame& frame) override;
    std::optional<int> done() const override { return std::nullopt; }

    static constexpr int kFramesApart = 12;

private:
    std::vector<std::string> tokens_;
    bool in_lobby_;
    std::size_t next_ = 0;
    int started_at_ = -1; // the frame the script started at
};

} // namespace carrom::client::app
