// Decoding of match states and rules configs (see match_json.hpp), read with JsonReader in the
// Document wording. Never throws: every value is type- and range-checked before use, and the
// first problem is returned with its path. Every field but "rule_set" is optional.

#include "carrom/proto/match_json.hpp"

#include "json_reader.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>

namespace carrom::proto {
namespace {

using Json = nlohmann::json;
using MaybeError = std::optional<Error>;
using namespace detail; // JsonReader, Wording, Range, field_path, index_path
using rules::MatchState;

constexpr int kMaxCount = 1000000;
constexpr int kMaxTurn = std::numeric_limits<int>::max();

Error inconsistent(std::string path, std::string message) {
    return Error{std::string(match_code::kInconsistentState), std::move(message), std::move(path)};
}

// Keeps out when key is absent (or r has an error).
void read_if_present(JsonReader& r, std::string_view key, int min, int max, int& out) {
    if (r.has(key)) {
        out = r.small_int(key, min, max);
    }
}

constexpr std::string_view kNotRuleCode = "is not a rule code";

struct IntField {
    std::string_view name;
    int rules::RulesConfig::*member;
    int lo;
    int hi;
};

struct FreestyleField {
    std::string_view name;
    int rules::FreestylePoints::*member;
};

MaybeError decode_freestyle(const Json& j, const std::string& path, rules::FreestylePoints& out) {
    const FreestyleField fields[] = {{"white", &rules::FreestylePoints::white},
                                     {"black", &rules::FreestylePoints::black},
                                     {"queen", &rules::FreestylePoints::queen},
                                     {"striker_penalty", &rules::FreestylePoints::striker_penalty},
                                     {"target", &rules::FreestylePoints::target}};
    JsonReader r(j, path, Wording::Document);
    if (r.only_keys({"white", "black", "queen", "striker_penalty", "target"})) {
        for (const FreestyleField& field : fields) {
            read_if_present(r, field.name, 0, kMaxFileScore, out.*(field.member));
        }
    }
    return r.error();
}

std::optional<int> team_or_null(JsonReader& r, std::string_view key, int teams) {
    if (r.find_optional(key) == nullptr) {
        return std::nullopt;
    }
    return r.small_int(key, 0, teams - 1);
}

MaybeError read_board_result(const Json& j, const std::string& path, int teams,
                             rules::BoardResult& out) {
    JsonReader r(j, path, Wording::Document);
    if (r.only_keys({"board", "winner_team", "points", "reason"})) {
        read_if_present(r, "board", 1, kMaxCount, out.board);
        out.winner_team = team_or_null(r, "winner_team", teams);
        read_if_present(r, "points", 0, kMaxFileScore, out.points);
        if (r.has("reason")) {
            out.reason = r.enumeration("reason", rules::kRuleCodeNames, out.reason, kNotRuleCode);
        }
    }
    return r.error();
}

MaybeError read_game_result(const Json& j, const std::string& path, int teams,
                            rules::GameResult& out) {
    JsonReader r(j, path, Wording::Document);
    if (r.only_keys({"winner_team", "reason"})) {
        out.winner_team = team_or_null(r, "winner_team", teams);
        if (r.has("reason")) {
            out.reason = r.enumeration("reason", rules::kRuleCodeNames, out.reason, kNotRuleCode);
        }
    }
    return r.error();
}

// 19 bodies with ids 0..18 (any order), the queen 0, nine black and nine white, at rest.
MaybeError decode_bodies(const Json& j, const std::string& path, MatchState& s) {
    if (!j.is_array() || j.size() != static_cast<std::size_t>(kCoinCount)) {
        return Error{std::string(scene_code::kWrongType),
                     path + " must be an array of the 19 pieces (ids 0..18)", path};
    }
    std::vector<Body> bodies(j.size());
    std::vector<bool> seen(j.size(), false);
    int black = 0;
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string at = index_path(path, i);
        auto body = decode_body(j[i], at);
        if (!body.ok()) {
            return body.error;
        }
        const Body& b = body.value;
        if (b.id >= kCoinCount || seen[static_cast<std::size_t>(b.id)]) {
            return inconsistent(field_path(at, "id"), "piece ids must be 0..18, each once");
        }
        const bool queen = b.kind == BodyKind::Queen;
        if (b.kind == BodyKind::Striker || queen != (b.id == kQueenId)) {
            return inconsistent(field_path(at, "kind"), "piece 0 is the queen; 1..18 are coins");
        }
        if (b.vel_px_s != Vec2{}) {
            return inconsistent(field_path(at, "vel"), "pieces are at rest between strokes");
        }
        black += b.kind == BodyKind::Black ? 1 : 0;
        seen[static_cast<std::size_t>(b.id)] = true;
        bodies[static_cast<std::size_t>(b.id)] = b;
    }
    if (black != 9) {
        return inconsistent(path, "there must be nine black and nine white coins");
    }
    if (auto problem = validate_scene(s.physics, bodies)) {
        const auto index = std::find_if(j.begin(), j.end(),
                                        [&](const Json& b) {
                                            return b.contains("id") && b["id"] == problem->body_id;
                                        }) -
                           j.begin();
        return Error{problem->code, problem->message,
                     field_path(index_path(path, static_cast<std::size_t>(index)), problem->field)};
    }
    s.bodies = std::move(bodies);
    return std::nullopt;
}

MaybeError decode_pocketed(const Json& j, const std::string& path, MatchState& s) {
    if (!j.is_array() || j.size() > static_cast<std::size_t>(kCoinCount)) {
        return Error{std::string(scene_code::kWrongType),
                     path + " must be an array of at most 19 pieces", path};
    }
    s.pocketed.clear();
    const int seats = static_cast<int>(s.seats.size());
    for (std::size_t i = 0; i < j.size(); ++i) {
        JsonReader r(j[i], index_path(path, i), Wording::Document);
        rules::PocketedPiece p;
        if (r.only_keys({"id", "seat", "turn_number"})) {
            p.id = r.small_int("id", 0, kCoinCount - 1);
            read_if_present(r, "seat", 0, seats - 1, p.seat);
            read_if_present(r, "turn_number", 0, kMaxTurn, p.turn_number);
        }
        if (!r.ok()) {
            return r.error();
        }
        p.kind = s.bodies[static_cast<std::size_t>(p.id)].kind;
        s.pocketed.push_back(p);
    }
    return std::nullopt;
}

// Without a "pocketed" list: the pocketed bodies in id order, credited to seat 0.
void derive_pocketed(MatchState& s) {
    s.pocketed.clear();
    for (const Body& b : s.bodies) {
        const bool out_of_play = b.id == kQueenId && s.rule_set == rules::RuleSet::DiscPool;
        if (b.pocketed && !out_of_play) {
            s.pocketed.push_back(rules::PocketedPiece{b.id, b.kind, 0, 0});
        }
    }
}

MaybeError decode_queen(const Json& j, const std::string& path, MatchState& s) {
    JsonReader r(j, path, Wording::Document);
    if (r.only_keys({"status", "seat"})) {
        if (r.has("status")) {
            s.queen.status = r.enumeration("status", kQueenStatusNames, s.queen.status);
        }
        s.queen.seat = -1;
        read_if_present(r, "seat", -1, static_cast<int>(s.seats.size()) - 1, s.queen.seat);
    }
    return r.error();
}

MaybeError check_pieces(const std::string& path, const MatchState& s) {
    for (const Body& b : s.bodies) {
        const auto listed =
            std::count_if(s.pocketed.begin(), s.pocketed.end(),
                          [&](const rules::PocketedPiece& p) { return p.id == b.id; });
        const bool out_of_play = b.id == kQueenId && s.rule_set == rules::RuleSet::DiscPool;
        const auto expected = b.pocketed && !out_of_play ? 1 : 0;
        if (listed != expected) {
            return inconsistent(field_path(path, "pocketed"),
                                "piece " + std::to_string(b.id) +
                                    (b.pocketed ? " is pocketed and must be listed once"
                                                : " is on the board and must not be listed"));
        }
    }
    return std::nullopt;
}

MaybeError check_queen(const std::string& path, const MatchState& s) {
    const std::string at = field_path(path, "queen");
    const bool off = s.bodies[kQueenId].pocketed;
    const bool discpool = s.rule_set == rules::RuleSet::DiscPool;
    using rules::QueenStatus;
    switch (s.queen.status) {
    case QueenStatus::OutOfPlay:
        return discpool && off ? MaybeError{}
                               : inconsistent(at, "only discpool has no queen (and it is off)");
    case QueenStatus::OnBoard:
        return !discpool && !off ? MaybeError{}
                                 : inconsistent(at, "an on_board queen must be on the board");
    case QueenStatus::PendingCover:
        if (s.queen.seat != s.turn_seat || s.phase != rules::Phase::AwaitingShot) {
            return inconsistent(at, "a queen pending cover waits for its seat's next stroke");
        }
        [[fallthrough]];
    case QueenStatus::Covered:
        return !discpool && off && s.queen.seat >= 0
                   ? MaybeError{}
                   : inconsistent(at, "a pocketed queen must be off the board and name a seat");
    }
    return std::nullopt;
}

MaybeError decode_counters(JsonReader& r, MatchState& s) {
    const auto teams = s.scores.size();
    const int seats = static_cast<int>(s.seats.size());
    const auto read_ints = [&r](std::string_view key, std::size_t size, int min, int max,
                                std::vector<int>& out) {
        if (r.has(key)) {
            out = r.int_array(key, min, max, size, true);
        }
    };
    read_ints("scores", teams, -kMaxFileScore, kMaxFileScore, s.scores);
    read_ints("dues_owed", teams, 0, kCoinCount, s.dues_owed);
    read_ints("missed_turns", s.seats.size(), 0, kMaxCount, s.missed_turns);
    read_if_present(r, "board", 1, kMaxCount, s.board);
    read_if_present(r, "breaker", 0, seats - 1, s.breaker);
    read_if_present(r, "turn_seat", 0, seats - 1, s.turn_seat);
    read_if_present(r, "turn_number", 0, kMaxTurn, s.turn_number);
    read_if_present(r, "strokes_this_board", 0, kMaxTurn, s.strokes_this_board);
    read_if_present(r, "break_tries", 0, s.config.break_tries - 1, s.break_tries);
    if (r.has("break_done")) {
        s.break_done = r.boolean("break_done");
    }
    if (r.has("phase")) {
        s.phase = r.enumeration("phase", kMatchPhaseNames, s.phase);
    }
    return r.error();
}

MaybeError decode_results(JsonReader& r, MatchState& s, const std::string& path) {
    const int teams = static_cast<int>(s.scores.size());
    if (r.has("boards")) {
        const Json& a = *r.find("boards");
        const std::string at = r.path_of("boards");
        if (!a.is_array() || a.size() > static_cast<std::size_t>(kMaxCount)) {
            return Error{std::string(scene_code::kWrongType), at + " must be an array", at};
        }
        s.boards.assign(a.size(), {});
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (auto e = read_board_result(a[i], index_path(at, i), teams, s.boards[i])) {
                return e;
            }
        }
    }
    if (const Json* result = r.find_optional("result")) {
        rules::GameResult decoded;
        if (auto e = read_game_result(*result, r.path_of("result"), teams, decoded)) {
            return e;
        }
        s.result = decoded;
    }
    if (s.result.has_value() != (s.phase == rules::Phase::GameOver)) {
        return inconsistent(field_path(path, "result"),
                            "a result is given exactly when the phase is game_over");
    }
    return std::nullopt;
}

bool check_state_keys(JsonReader& r) {
    return r.only_keys({"rule_set",     "rules",
                        "physics",      "seats",
                        "bodies",       "pocketed",
                        "scores",       "dues_owed",
                        "missed_turns", "board",
                        "breaker",      "turn_seat",
                        "turn_number",  "strokes_this_board",
                        "break_tries",  "break_done",
                        "queen",        "phase",
                        "boards",       "result"});
}

} // namespace

Decoded<rules::BoardResult> decode_board_result(const nlohmann::json& j, int teams,
                                                const std::string& path) {
    Decoded<rules::BoardResult> out;
    out.error = read_board_result(j, path, teams, out.value);
    return out;
}

Decoded<rules::GameResult> decode_game_result(const nlohmann::json& j, int teams,
                                              const std::string& path) {
    Decoded<rules::GameResult> out;
    out.error = read_game_result(j, path, teams, out.value);
    return out;
}

Decoded<rules::RulesConfig> decode_rules_config(const nlohmann::json& j,
                                                const rules::RulesConfig& base,
                                                const std::string& path) {
    const IntField ints[] = {
        {"seat_count", &rules::RulesConfig::seat_count, 2, 4},
        {"first_breaker", &rules::RulesConfig::first_breaker, 0, 3},
        {"missed_turns_to_lose", &rules::RulesConfig::missed_turns_to_lose, 1, 1000},
        {"target_points", &rules::RulesConfig::target_points, 1, kMaxFileScore},
        {"max_boards", &rules::RulesConfig::max_boards, 1, 1000},
        {"queen_points", &rules::RulesConfig::queen_points, 0, kMaxFileScore},
        {"queen_points_limit", &rules::RulesConfig::queen_points_limit, 0, kMaxFileScore},
        {"board_points_cap", &rules::RulesConfig::board_points_cap, 1, kMaxFileScore},
        {"break_tries", &rules::RulesConfig::break_tries, 1, 100},
    };
    rules::RulesConfig out = base;
    JsonReader r(j, path, Wording::Document);
    if (r.only_keys({"seat_count", "first_breaker", "shot_clock_s", "shot_clock_grace_s",
                     "missed_turns_to_lose", "target_points", "max_boards", "queen_points",
                     "queen_points_limit", "board_points_cap", "break_tries", "freestyle"})) {
        for (const IntField& field : ints) {
            read_if_present(r, field.name, field.lo, field.hi, out.*(field.member));
        }
        for (const auto& [key, member] :
             {std::pair{"shot_clock_s", &rules::RulesConfig::shot_clock_s},
              std::pair{"shot_clock_grace_s", &rules::RulesConfig::shot_clock_grace_s}}) {
            if (r.has(key)) {
                out.*member = r.number(key, Range{0.0, 3600.0});
            }
        }
        if (const Json* freestyle = r.has("freestyle") ? r.find("freestyle") : nullptr) {
            r.merge(decode_freestyle(*freestyle, r.path_of("freestyle"), out.freestyle));
        }
    }
    if (r.ok()) {
        if (auto problem = rules::validate_rules_config(out)) {
            r.merge(Error{std::string(scene_code::kInvalidConfig), problem->message,
                          field_path(path, problem->field)});
        }
    }
    return {out, r.error()};
}

Decoded<rules::MatchState> decode_match_state(const nlohmann::json& j, const std::string& path) {
    Decoded<MatchState> out;
    const auto fail = [&out](const std::optional<Error>& e) {
        out.error = e;
        return out;
    };
    JsonReader r(j, path, Wording::Document);
    rules::RuleSet rule_set = rules::RuleSet::Icf;
    if (check_state_keys(r) && r.has("rule_set")) {
        rule_set = r.enumeration("rule_set", rules::kRuleSetNames, rule_set);
    }
    rules::RulesConfig config;
    if (const Json* rules = r.has("rules") ? r.find("rules") : nullptr) {
        auto decoded = decode_rules_config(*rules, {}, r.path_of("rules"));
        r.merge(decoded.error);
        config = decoded.value;
    }
    PhysicsConfig physics;
    if (const Json* physics_json = r.has("physics") ? r.find("physics") : nullptr) {
        auto decoded = decode_config(*physics_json, {}, r.path_of("physics"));
        r.merge(decoded.error);
        physics = decoded.value;
    }
    if (!r.ok()) {
        return fail(r.error());
    }
    MatchState s = rules::new_match(rule_set, config, physics);
    if (r.has("bodies")) {
        if (auto e = decode_bodies(*r.find("bodies"), r.path_of("bodies"), s)) {
            return fail(e);
        }
        derive_pocketed(s);
        if (!s.bodies[kQueenId].pocketed && rule_set != rules::RuleSet::DiscPool) {
            s.queen = {};
        }
    }
    if (r.has("pocketed")) {
        if (auto e = decode_pocketed(*r.find("pocketed"), r.path_of("pocketed"), s)) {
            return fail(e);
        }
    }
    if (r.has("queen")) {
        if (auto e = decode_queen(*r.find("queen"), r.path_of("queen"), s)) {
            return fail(e);
        }
    }
    if (auto e = decode_counters(r, s)) {
        return fail(e);
    }
    if (auto e = decode_results(r, s, path)) {
        return fail(e);
    }
    if (auto e = check_pieces(path, s)) {
        return fail(e);
    }
    if (auto e = check_queen(path, s)) {
        return fail(e);
    }
    out.value = std::move(s);
    return out;
}

Decoded<Shot> decode_rules_shot(const nlohmann::json& j, const std::string& path) {
    Shot out;
    JsonReader r(j, path, Wording::Document);
    if (r.only_keys({"x", "angle", "power"}) && r.require({"x", "angle", "power"})) {
        const double big = std::numeric_limits<double>::max();
        out.x_px = r.number("x", Range{-big, big});
        out.angle_rad = r.number("angle", Range{-big, big});
        out.power = r.number("power", Range{-big, big});
    }
    return {out, r.error()};
}

} // namespace carrom::proto
