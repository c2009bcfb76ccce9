#pragma once
// Golden cases of the match model (client/src/match_model.cpp, web/js/match_model.js): a
// recorded server stream replayed message by message at its arrival times, and after each
// message what the HUD shows (the view), the HUD lines posted, the time the board is drawn at
// and the sounds that became due, with a render at the message's arrival.

#include "carrom/client/match_model.hpp"
#include "carrom/golden/golden_json.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace carrom::golden {

// The HUD's view as a case file keeps it (names as on the wire); outside a room only that.
nlohmann::json view_json(const client::MatchModel& model);

// One entry per stream line: {"render_s", and only when they change or happen: "view", "log"
// [[text, tone]], "sounds" [[kind, time_s, volume]]}.
nlohmann::json model_steps(const std::vector<StreamLine>& stream);

// A stream for the sound cues' limits, made from a recorded one: its lines up to the first
// delta of the first shot, then 600 audible events of that shot arriving at once (pairs of
// clicks at one instant with a cushion 3 ms later, every 6 ms of the shot: more than the 512
// cues kept), then pongs later and later, each a render that takes the cues due by then (those
// over 0.25 s late are dropped).
std::vector<StreamLine> cue_stream(const std::vector<StreamLine>& recorded);

} // namespace carrom::golden
