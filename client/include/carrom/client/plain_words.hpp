#pragma once
// Sentences for people: what the server and the link report, in plain words.

#include "carrom/body.hpp"
#include "carrom/client/coins_left.hpp"
#include "carrom/proto/error.hpp"
#include "carrom/proto/types.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace carrom::client {

// "1 due", "3 dues".
std::string count_words(int count, std::string_view one, std::string_view many);
// "2 white coins and the queen", "the striker".
std::string pocket_list(const std::vector<BodyKind>& kinds);
std::string queen_sentence(const proto::QueenInfo& queen, const std::string& seat_name);
// What a seat has left to pocket: "7 white + queen left", "1 black left", "12 coins left",
// "no white left".
std::string coins_left_text(const SeatCoins& coins);
// An error from the server, said for a player (falls back to the server's own sentence).
std::string error_sentence(const proto::Error& error);
std::string rule_set_name(proto::RuleSet rule_set);
// The game's target for the HUD: "to 25, scored at board end" (icf, seed: a board's
// points come when it ends, so the score stays 0 while coins go in), "first to 40 points"
// (freestyle: every stroke scores), "to 25 points" (discpool).
std::string target_words(proto::RuleSet rule_set, int target_points);

// A foul, in the warning colour: "Foul by Asha: The striker went into a pocket." (the server's
// sentence for the foul).
std::string foul_sentence(const std::string& name, const std::string& message);
// What a stroke's fouls cost besides the turn and dues: the pieces that went back to the centre and
// the points lost (a negative stroke score), e.g. "Cost: 1 white coin back to the centre and
// 10 points". Empty when nothing of that was lost.
std::string foul_cost(const std::vector<BodyKind>& returned, int points);
// A stroke's points in a rule set that scores each stroke (freestyle): " (+20)", " (-10)";
// empty for 0.
std::string stroke_points(int points);
// A team's unpaid dues: "Asha owes 1 due: the next coin Asha pockets goes back to the centre";
// `subject` names the team (plural: a pair, "Asha & Ravi owe 2 dues: ...").
std::string dues_sentence(const std::string& subject, bool plural, int owed);
// Who gave up the game and who won it: "Asha left the match: Ravi wins by forfeit",
// "Asha did not come back in time: you win by forfeit". `reason`: game_end's "left" or
// "forfeit"; `winner`: the winners as a subject ("you", "Ravi", "Ravi & Dev", "your team");
// `plural`: the winners are a pair.
std::string forfeit_sentence(const std::string& leaver, const std::string& reason,
                             const std::string& winner, bool plural);

} // namespace carrom::client
