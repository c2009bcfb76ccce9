#pragma once
// What a screenshot shows (and a game's final state), as JSON written next to the PNG: the room,
// the turn and phase, the window layout and every drawn piece in board px and in window px. Tests
// compare it with what the server reported and with the pixels of the PNG.

#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/client/screen_mapping.hpp"

#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace carrom::client {

struct ReportContext {
    double window_w = 0.0; // window px
    double window_h = 0.0;
    int shots_seen = 0;           // shot results received so far
    std::optional<Rect> overlay;  // window px covered by the messages and the room code
    PredictionStats prediction;   // the own strokes predicted and the server's corrections
    std::string ui_json = "null"; // the window's menus and side area, a JSON value ("ui")
    const std::deque<HudLine>* said = nullptr; // the lines the player was told (MatchModel)
};

// One JSON object (one line): {"room", "you", "turn", "phase", "flipped" (the view is turned half
// a turn), "bottom_side" (the side drawn at the bottom: "bottom", "right", "top", "left"), "window"
// {w, h}, "board" {x, y, side} (window px), "shots_seen", "scores" [per seat], "names" [per seat,
// "" for a free one], "bodies" [{"id",
// "kind", "x", "y" (board px), "screen_x", "screen_y" (window px), "scale", "alpha"}] in drawing
// order (id -1: the striker being placed), "overlay" {x, y, w, h} or null, "prediction"
// {"strokes", "corrections", "max_difference_px"} (the own strokes predicted, the bodies the
// server corrected, the largest difference seen), "ui" (ReportContext::ui_json: the match
// window's "open" dialog, "tip", "rules_tab", "settings", "side", "messages" [{"text", x, y, w,
// h}], "bar_buttons", "leave_text"), "board_summary" {"title", "points", "colours"}
// (board_summary_text; null without a board that ended), "said" (as final_state_json's)}.
std::string board_report_json(const MatchView& view, const std::vector<RenderedBody>& bodies,
                              const ScreenMapping& mapping, const ReportContext& context);

// The final state of a game (carrom-client --final-state), one JSON object (one line): {"room",
// "you", "winner" (seat, -1 a draw), "reason" (game_end_name: the rule code, as the journal names
// the end), "scores" [per seat, game_end's], "bodies" [{"id", "kind", "x", "y" (board px, as the
// server sent them), "pocketed"}] of the newest board in id order, "game_over" {"title",
// "reason", "score", "can_rematch", "opponent_left", "waiting"} (game_over_text, as the panel
// shows it; null before the end), "said" [{"text", "tone": "info"/"good"/"foul"/"error"}] (the
// lines the player was told, oldest first; empty without a transcript)}.
std::string final_state_json(const MatchView& view, const std::vector<BodyState>& board,
                             const std::deque<HudLine>& said = {});

} // namespace carrom::client
