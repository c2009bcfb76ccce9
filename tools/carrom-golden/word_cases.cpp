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
    auto kinds_of = [](const nlohmann::json& list) {
        std::vector<BodyKind> kinds;
        for (const nlohmann::json& k : list) {
            kinds.push_back(kind_named(k.get<std::string>()));
        }
        return kinds;
    };
    for (const nlohmann::json& f : input.at("fouls")) {
        out["fouls"].push_back(
            client::foul_sentence(f.at(0).get<std::string>(), f.at(1).get<std::string>()));
    }
    for (const nlohmann::json& c : input.at("costs")) {
        out["costs"].push_back(client::foul_cost(kinds_of(c.at(0)), c.at(1).get<int>()));
    }
    for (const nlohmann::json& p : input.at("stroke_points")) {
        out["stroke_points"].push_back(client::stroke_points(p.get<int>()));
    }
    for (const nlohmann::json& d : input.at("dues")) {
        out["dues"].push_back(client::dues_sentence(d.at(0).get<std::string>(), d.at(1).get<bool>(),
                                                    d.at(2).get<int>()));
    }
    for (const nlohmann::json& f : input.at("forfeits")) {
        out["forfeits"].push_back(
            client::forfeit_sentence(f.at(0).get<std::string>(), f.at(1).get<std::string>(),
                                     f.at(2).get<std::string>(), f.at(3).get<bool>()));
    }
    for (const nlohmann::json& t : input.at("targets")) {
        proto::RuleSet rule_set = proto::RuleSet::Icf;
        proto::parse(t.at(0).get<std::string>(), rule_set);
        out["targets"].push_back(client::target_words(rule_set, t.at(1).get<int>()));
    }
    for (const nlohmann::json& c : input.at("coins_left")) {
        const client::CoinsOnBoard board{c.at(0).get<int>(), c.at(1).get<int>(),
                                         c.at(2).get<bool>()};
        proto::RuleSet rule_set = proto::RuleSet::Icf;
        proto::parse(c.at(3).get<std::string>(), rule_set);
        proto::Colour colour = proto::Colour::None;
        proto::parse(c.at(4).get<std::string>(), colour);
        const auto coins = client::seat_coins(board, rule_set, colour);
        out["coins_left"].push_back(coins ? client::coins_left_text(*coins) : std::string());
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
    nlohmann::json words = {{"count",
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
    // The texts of a newcomer's first games (fouls and what they cost, dues, forfeits, the HUD's
    // target and coins left), as data: nlohmann's braces would read a pair of strings as a key
    // and its value.
    words.update(nlohmann::json::parse(R"j({
      "fouls": [["Asha", "The striker went into a pocket."],
                ["Ravi", "The shot clock ran out; the turn passes. 2 more missed turns in a row lose the game."]],
      "costs": [[[], 0], [["white"], 0], [["white", "white", "queen"], 0], [[], -10], [["black"], -1]],
      "stroke_points": [0, 20, -10],
      "targets": [["icf", 25], ["seed", 29], ["freestyle", 40], ["discpool", 9], ["icf", 1]],
      "coins_left": [[9, 9, true, "icf", "white"], [1, 0, false, "icf", "black"],
                     [0, 4, true, "seed", "white"], [0, 0, true, "icf", "white"],
                     [5, 7, true, "freestyle", "none"], [1, 0, false, "freestyle", "none"],
                     [3, 3, true, "discpool", "black"], [3, 3, true, "icf", "none"]],
      "dues": [["Asha", false, 1], ["Asha", false, 2], ["Asha & Ravi", true, 1]],
      "forfeits": [["Asha", "left", "Ravi", false], ["Asha", "forfeit", "you", true],
                   ["Asha", "left", "your team", false], ["Mira", "left", "Ravi & Dev", true]]
    })j"));
    return words;
}

} // namespace carrom::golden
