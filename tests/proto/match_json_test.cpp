// JSON of the rules engine: match states round-trip exactly, every bad field is named by its
// path with a stable code, and outcomes carry every rule decision.

#include "carrom/proto/match_json.hpp"

#include <gtest/gtest.h>

namespace carrom::proto {
namespace {

using Json = nlohmann::json;
using rules::MatchState;

MatchState fresh(rules::RuleSet rule_set = rules::RuleSet::Icf) {
    rules::RulesConfig config;
    config.shot_clock_s = 0.0;
    return rules::new_match(rule_set, config, PhysicsConfig{});
}

rules::StrokePhysics pocketing(const MatchState& m, std::vector<int> ids, bool striker = false) {
    rules::StrokePhysics p;
    p.bodies = m.bodies;
    for (int id : ids) {
        p.bodies[static_cast<std::size_t>(id)].pocketed = true;
    }
    p.pocket_order = ids;
    p.striker_pocketed = striker;
    return p;
}

rules::StrokeResult stroke(const MatchState& m, std::vector<int> ids, bool striker = false) {
    return rules::judge_stroke(m, m.turn_seat, Shot{300.0, -1.0, 5.0},
                               pocketing(m, std::move(ids), striker));
}

Error decode_error(const Json& j) {
    const auto decoded = decode_match_state(j);
    EXPECT_FALSE(decoded.ok()) << j.dump();
    return decoded.error.value_or(Error{});
}

void expect_round_trip(const MatchState& s) {
    const Json j = match_state_to_json(s);
    const auto decoded = decode_match_state(j);
    ASSERT_TRUE(decoded.ok()) << decoded.error->path << ": " << decoded.error->message;
    EXPECT_EQ(match_state_to_json(decoded.value), j);
}

TEST(MatchJson, NewMatchesRoundTrip) {
    for (rules::RuleSet r : {rules::RuleSet::Icf, rules::RuleSet::Seed, rules::RuleSet::Freestyle,
                             rules::RuleSet::DiscPool}) {
        expect_round_trip(fresh(r));
    }
    rules::RulesConfig doubles;
    doubles.seat_count = 4;
    expect_round_trip(rules::new_match(rules::RuleSet::Icf, doubles, PhysicsConfig{}));
}

TEST(MatchJson, MidGameStatesRoundTrip) {
    MatchState m = fresh();
    m = stroke(m, {2}).state;        // white in, seat 0 again
    m = stroke(m, {kQueenId}).state; // queen pending cover
    expect_round_trip(m);
    m = stroke(m, {}, true).state;  // foul: queen back, due paid with coin 2
    m = stroke(m, {1}, true).state; // seat 1: striker with a black, owes a due
    EXPECT_EQ(m.dues_owed[1], 1);
    expect_round_trip(m);
    m = rules::forfeit(m, 0).state;
    expect_round_trip(m);
}

TEST(MatchJson, EncodesNamesNotNumbers) {
    MatchState m = fresh(rules::RuleSet::Freestyle);
    m = stroke(m, {kQueenId}).state;
    const Json j = match_state_to_json(m);
    EXPECT_EQ(j["rule_set"], "freestyle");
    EXPECT_EQ(j["phase"], "awaiting_shot");
    EXPECT_EQ(j["queen"], (Json{{"status", "pending_cover"}, {"seat", 0}}));
    EXPECT_EQ(j["seats"][1]["side"], "top");
    EXPECT_EQ(j["pocketed"], (Json::array({{{"id", 0}, {"seat", 0}, {"turn_number", 0}}})));
    EXPECT_EQ(j["physics"], Json::object()); // defaults: no overrides
    EXPECT_EQ(j["rules"]["freestyle"]["white"], 20);
    EXPECT_TRUE(j["result"].is_null());
}

TEST(MatchJson, MissingFieldsTakeNewMatchDefaults) {
    const auto empty = decode_match_state(Json::object());
    ASSERT_TRUE(empty.ok());
    EXPECT_EQ(match_state_to_json(empty.value),
              match_state_to_json(rules::new_match(rules::RuleSet::Icf, {}, PhysicsConfig{})));
    const auto seed = decode_match_state(
        {{"rule_set", "seed"}, {"scores", {3, 4}}, {"rules", {{"shot_clock_s", 0}}}});
    ASSERT_TRUE(seed.ok());
    EXPECT_EQ(seed.value.rule_set, rules::RuleSet::Seed);
    EXPECT_EQ(seed.value.scores, (std::vector<int>{3, 4}));
    EXPECT_EQ(seed.value.config.shot_clock_s, 0.0);
}

TEST(MatchJson, PocketedListIsDerivedFromBodiesWhenAbsent) {
    Json j = match_state_to_json(fresh());
    j["bodies"][4]["pocketed"] = true;
    j.erase("pocketed");
    const auto decoded = decode_match_state(j);
    ASSERT_TRUE(decoded.ok());
    ASSERT_EQ(decoded.value.pocketed.size(), 1u);
    EXPECT_EQ(decoded.value.pocketed[0].id, 4);
    EXPECT_EQ(decoded.value.pocketed[0].kind, BodyKind::White);
}

TEST(MatchJson, BadFieldsAreNamed) {
    const Json base = match_state_to_json(fresh());
    auto with = [&base](const std::string& key, Json value) {
        Json j = base;
        j[key] = std::move(value);
        return j;
    };
    Error e = decode_error(with("colour", 1));
    EXPECT_EQ(e.code, "unknown_field");
    EXPECT_EQ(e.path, "state.colour");
    e = decode_error(with("rule_set", "snooker"));
    EXPECT_EQ(e.code, "bad_value");
    EXPECT_EQ(e.path, "state.rule_set");
    e = decode_error(with("rule_set", 3));
    EXPECT_EQ(e.code, "wrong_type");
    e = decode_error(with("turn_seat", 2));
    EXPECT_EQ(e.code, "out_of_range");
    EXPECT_EQ(e.path, "state.turn_seat");
    e = decode_error(with("scores", Json::array({1, 2, 3})));
    EXPECT_EQ(e.path, "state.scores");
    e = decode_error(with("scores", Json::array({1, "2"})));
    EXPECT_EQ(e.path, "state.scores[1]");
    e = decode_error(with("dues_owed", Json::array({0, -1})));
    EXPECT_EQ(e.code, "out_of_range");
    e = decode_error(with("turn_number", 1e300));
    EXPECT_EQ(e.code, "wrong_type");
    e = decode_error(with("phase", "paused"));
    EXPECT_EQ(e.path, "state.phase");
    e = decode_error(with("rules", {{"seat_count", 3}}));
    EXPECT_EQ(e.code, "invalid_config");
    EXPECT_EQ(e.path, "state.rules.seat_count");
    e = decode_error(with("rules", {{"freestyle", {{"gold", 1}}}}));
    EXPECT_EQ(e.path, "state.rules.freestyle.gold");
    e = decode_error(with("physics", {{"coin_radius_px", -1}}));
    EXPECT_EQ(e.path.rfind("state.physics", 0), 0u) << e.path;
}

TEST(MatchJson, BodiesAreCheckedPieceByPiece) {
    const Json base = match_state_to_json(fresh());
    Json j = base;
    j["bodies"].erase(18);
    EXPECT_EQ(decode_error(j).path, "state.bodies");
    j = base;
    j["bodies"][3]["id"] = 5;
    EXPECT_EQ(decode_error(j).code, "inconsistent_state");
    j = base;
    j["bodies"][0]["kind"] = "black";
    EXPECT_EQ(decode_error(j).path, "state.bodies[0].kind");
    j = base;
    j["bodies"][2]["kind"] = "black";
    EXPECT_EQ(decode_error(j).code, "inconsistent_state"); // ten blacks
    j = base;
    j["bodies"][5]["vel"] = {1.0, 0.0};
    EXPECT_EQ(decode_error(j).path, "state.bodies[5].vel");
    j = base;
    j["bodies"][7]["pos"] = {300.0, 300.0}; // on the queen
    const Error overlap = decode_error(j);
    EXPECT_EQ(overlap.code, "overlap");
    j = base;
    j["bodies"][7]["pos"] = {10.0, 300.0};
    EXPECT_EQ(decode_error(j).code, "outside_cushions");
    EXPECT_EQ(decode_error(j).path, "state.bodies[7].pos.x");
}

TEST(MatchJson, FieldsMustAgreeWithEachOther) {
    const Json base = match_state_to_json(fresh());
    Json j = base;
    j["bodies"][4]["pocketed"] = true; // pocketed but not in the list
    EXPECT_EQ(decode_error(j).code, "inconsistent_state");
    EXPECT_EQ(decode_error(j).path, "state.pocketed");
    j = base;
    j["pocketed"] = {{{"id", 4}, {"seat", 0}}}; // listed but on the board
    EXPECT_EQ(decode_error(j).code, "inconsistent_state");
    j = base;
    j["queen"] = {{"status", "covered"}, {"seat", 0}}; // the queen body is on the board
    EXPECT_EQ(decode_error(j).path, "state.queen");
    j = base;
    j["phase"] = "game_over"; // without a result
    EXPECT_EQ(decode_error(j).path, "state.result");
    j = base;
    j["result"] = {{"winner_team", 0}, {"reason", "forfeit"}}; // while still playing
    EXPECT_EQ(decode_error(j).code, "inconsistent_state");
    j = base;
    j["rule_set"] = "discpool"; // discpool has no queen on the board
    EXPECT_EQ(decode_error(j).path, "state.queen");
    j = base;
    j["bodies"][0]["pocketed"] = true;
    j["pocketed"] = {{{"id", 0}, {"seat", 0}}};
    j["queen"] = {{"status", "pending_cover"}, {"seat", 1}}; // seat 1 is not to shoot
    EXPECT_EQ(decode_error(j).path, "state.queen");
    j["queen"] = {{"status", "pending_cover"}, {"seat", 0}};
    EXPECT_TRUE(decode_match_state(j).ok());
}

TEST(MatchJson, ShotOutcomeCarriesEveryDecision) {
    MatchState m = fresh();
    m.bodies[2].pocketed = true;
    m.pocketed.push_back({2, BodyKind::White, 0, 0});
    const rules::StrokeResult r = stroke(m, {4, 1}, true);
    const Json j = shot_outcome_to_json(r.outcome, false);
    EXPECT_EQ(j["seat"], 0);
    EXPECT_EQ(j["shot_taken"], true);
    EXPECT_EQ(j["shot"]["power"], 5.0);
    EXPECT_EQ(j["pocketed"], (Json::array({4, 1})));
    EXPECT_EQ(j["striker_pocketed"], true);
    EXPECT_EQ(j["fouls"], (Json::array({{{"code", "striker_pocketed"}, {"seat", 0}}})));
    ASSERT_EQ(j["returned"].size(), 2u);
    EXPECT_EQ(j["returned"][0]["id"], 4);
    EXPECT_EQ(j["returned"][0]["kind"], "white");
    EXPECT_EQ(j["returned"][0]["reason"], "striker_pocketed");
    EXPECT_EQ(j["returned"][1]["reason"], "due_paid");
    EXPECT_EQ(j["dues"], (Json{{"incurred", 1}, {"paid", 1}, {"owed", 0}}));
    EXPECT_EQ(j["queen"]["after"]["status"], "on_board");
    EXPECT_EQ(j["score_changes"], (Json::array({0, 0})));
    EXPECT_EQ(j["extra_stroke"], true);
    EXPECT_EQ(j["next_seat"], 0);
    EXPECT_TRUE(j["board_end"].is_null());
    EXPECT_FALSE(j.contains("physics"));
    EXPECT_TRUE(shot_outcome_to_json(r.outcome, true).contains("physics"));
}

TEST(MatchJson, BoardAndGameEndsAreEncoded) {
    const rules::PlayResult r = rules::forfeit(fresh(), 1);
    const Json j = shot_outcome_to_json(r.outcome, true);
    EXPECT_EQ(j["game_end"], (Json{{"winner_team", 0}, {"reason", "forfeit"}}));
    EXPECT_TRUE(j["physics"].is_null());
    EXPECT_TRUE(j["shot"].is_null());
    EXPECT_EQ(
        board_result_to_json({3, std::nullopt, 0, rules::RuleCode::CoinsExhausted}),
        (Json{
            {"board", 3}, {"winner_team", nullptr}, {"points", 0}, {"reason", "coins_exhausted"}}));
}

TEST(MatchJson, RulesShotNeedsThreeFiniteNumbers) {
    const auto ok = decode_rules_shot({{"x", 300}, {"angle", -1.5}, {"power", 10}});
    ASSERT_TRUE(ok.ok());
    EXPECT_EQ(ok.value.x_px, 300.0);
    EXPECT_EQ(ok.value.power, 10.0);
    const auto missing = decode_rules_shot({{"x", 300}, {"angle", -1.5}});
    EXPECT_EQ(missing.error->code, "missing_field");
    EXPECT_EQ(missing.error->path, "shot.power");
    const auto text = decode_rules_shot({{"x", "300"}, {"angle", 0}, {"power", 1}});
    EXPECT_EQ(text.error->code, "wrong_type");
    EXPECT_EQ(text.error->path, "shot.x");
    EXPECT_EQ(decode_rules_shot(Json::array()).error->code, "wrong_type");
}

TEST(MatchJson, RulesConfigRoundTrips) {
    rules::RulesConfig c;
    c.target_points = 29;
    c.freestyle.queen = 40;
    c.shot_clock_s = 15.5;
    const auto decoded = decode_rules_config(rules_config_to_json(c));
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(rules_config_to_json(decoded.value), rules_config_to_json(c));
    EXPECT_EQ(decode_rules_config({{"shot_clock_s", -1}}).error->code, "out_of_range");
}

TEST(MatchJson, EnumNamesRoundTrip) {
    for (auto p : {rules::Phase::AwaitingShot, rules::Phase::BoardOver, rules::Phase::GameOver}) {
        rules::Phase out = rules::Phase::GameOver;
        ASSERT_TRUE(parse_phase(to_string(p), out));
        EXPECT_EQ(out, p);
    }
    for (auto q : {rules::QueenStatus::OnBoard, rules::QueenStatus::PendingCover,
                   rules::QueenStatus::Covered, rules::QueenStatus::OutOfPlay}) {
        rules::QueenStatus out = rules::QueenStatus::OnBoard;
        ASSERT_TRUE(parse_queen_status(to_string(q), out));
        EXPECT_EQ(out, q);
    }
    rules::Phase out = rules::Phase::BoardOver;
    EXPECT_FALSE(parse_phase("over", out));
}

} // namespace
} // namespace carrom::proto
