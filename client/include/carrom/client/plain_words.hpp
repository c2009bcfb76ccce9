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

} // namespace carrom::client
