#include "carrom/golden/word_cases.hpp"

#include "carrom/client/how_to_play.hpp"
#include "carrom/client/plain_words.hpp"
#include "carrom/golden/golden_json.hpp"
#include "carrom/proto/error.hpp"
#include "carrom/proto/types.hpp"

#include <string>
#include <vector>

namespace carrom::golden {
nlohmann::json replay_words(const nlohmann::json& input) {
    nlohmann::json out;
    for (const nlohmann::json& c : input.at("count")) {
        out["count"].push_back(client::count_words(c.at(0).get<int>(), c.at(1).get<std::string>(),
                                                   c.at(2).get<std::string>()));
    }
    for (const nlohmann::json& list : input.at("pockets")) {
        std::vector<BodyKind> kinds;
        for (const nlohmann::json& k : list) {
            kinds.push_back(kind_named(k.get<std::string>()));
        }
        out["pockets"].push_back(client::pocket_list(kinds));
    }
    for (const nlohmann::json& q : input.at("queen")) {
        proto::QueenInfo queen;
        proto::parse(q.at(0).get<std::string>(), queen.state);
        queen.seat = q.at(1).get<int>();
        out["queen"].push_back(client::queen_sentence(queen, q.at(2).get<std::string>()));
    }
    for (const nlohmann::json& e : input.at("errors")) {
        proto::Error error;
        error.code = e.at(0).get<std::string>();
        error.message = e.at(1).get<std::string>();
        out["errors"].push_back(client::error_sentence(error));
    }
    for (const nlohmann::json& r : input.at("rule_sets")) {
        proto::RuleSet rule_set = proto::RuleSet::Icf;
        proto::parse(r.get<std::string>(), rule_set);
        out["rule_sets"].push_back(client::rule_set_name(rule_set));
        const client::HowToPlay h = client::how_to_play(rule_set);
        out["how_to_play"].push_back({{"title", h.title},
                                      {"rules", h.rules},
                                      {"foul", h.foul},
                                      {"walkthrough", client::walkthrough_steps(rule_set)}});
    }
    out["controls"] = client::controls_help();
    return out;
}

nlohmann::json words_input() {
    namespace c = proto::code;
    nlohmann::json errors = nlohmann::json::array();
    for (const std::string_view code :
         {c::kRoomNotFound, c::kRoomFull, c::kNotYourTurn, c::kStaleTurn, c::kInMotion,
          c::kIllegalPlacement, c::kIllegalShot, c::kSpectator, c::kBadToken, c::kServerFull,
          c::kTooManyRooms, c::kRateLimited, c::kShuttingDown, c::kWrongPhase, c::kInternal}) {
        errors.push_back({code, "The server's own words."});
    }
    errors.push_back({"not_a_code", ""});
    errors.push_back({"not_a_code", "Something happened."});
    return {{"count",
             {{0, "due", "dues"},
              {1, "due", "dues"},
              {2, "due", "dues"},
              {1, "piece", "pieces"},
              {12, "piece", "pieces"}}},
            {"pockets",
             {nlohmann::json::array(),
              {"white"},
              {"black", "black"},
              {"white", "white", "queen"},
              {"queen", "black", "white", "striker"},
              {"striker"},
              {"white", "black", "white"}}},
            {"queen",
             {{"on_board", -1, "Asha"},
              {"pending", 0, "Asha"},
              {"covered", 1, "Ravi"},
              {"none", -1, "Asha"}}},
            {"errors", errors},
            {"rule_sets", {"icf", "seed", "freestyle", "discpool"}}};
}

} // namespace carrom::golden
