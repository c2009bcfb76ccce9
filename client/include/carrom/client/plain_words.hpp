#pragma once
// Sentences for people: what the server and the link report, in plain words.

#include "carrom/body.hpp"
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
std::string game_end_sentence(int winner, bool we_won, const std::string& winner_name,
                              std::string_view reason);
// An error from the server, said for a player (falls back to the server's own sentence).
std::string error_sentence(const proto::Error& error);
std::string rule_set_name(proto::RuleSet rule_set);

} // namespace carrom::client
