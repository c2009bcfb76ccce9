// Decoding of match states and rules configs (see match_json.hpp). Never throws: every value is
// type- and range-checked before use, and the first problem is returned with its path.

#include "carrom/proto/match_json.hpp"

#include "scene_json_read.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>

namespace carrom::proto {
namespace {

using namespace scene_json_detail;
using rules::MatchState;

constexpr int kMaxCount = 1000000;
constexpr int kMaxTurn = std::numeric_limits<int>::max();

// Reads optional fields of one object in sequence; after the first problem it reads nothing.
class Fields {
public:
    Fields(const Json& j, std::string path) : j_(j), path_(std::move(path)) {}

    MaybeError error;

    bool has(std::string_view key) const { return !error && j_.contains(key); }
    std::string at(std::string_view key) const { return field_path(path_, key); }
    const Json& operator[](std::string_view key) const { return j_[std::string(key)]; }

    void integer(std::string_view key, int lo, int hi, int& out) {
        std::int64_t v = 0;
        if (has(key) && !(error = read_integer((*this)[key], at(key), lo, hi, v))) {
            out = static_cast<int>(v);
        }
    }
    void number(std::string_view key, Range range, double& out) {
        if (has(key)) {
            error = read_number((*this)[key], at(key), range, out);
        }
    }
    void boolean(std::string_view key, bool& out) {
        if (has(key)) {
            error = read_bool((*this)[key], at(key), out);
        }
    }
    template <class E>
    void enumeration(std::string_view key, bool (*parse)(std::string_view, E&), E& out) {
        std::string text;
        if (!has(key) || (error = read_string((*this)[key], at(key), 64, text))) {
            return;
        }
        if (!parse(text, out)) {
            error = make_error(scene_code::kBadValue, at(key),
                               at(key) + " has no value \"" + text + "\"");
        }
    }
    // An array of exactly `size` integers in [lo, hi].
    void int_array(std::string_view key, std::size_t size, int lo, int hi, std::vector<int>& out) {
        if (!has(key)) {
            return;
        }
        const Json& a = (*this)[key];
        if (!a.is_array() || a.size() != size) {
            error =
                make_error(scene_code::kWrongType, at(key),
                           at(key) + " must be an array of " + std::to_string(size) + " integers");
            return;
        }
        for (std::size_t i = 0; i < size && !error; ++i) {
            std::int64_t v = 0;
            error = read_integer(a[i], index_path(at(key), i), lo, hi, v);
            out[i] = static_cast<int>(v);
        }
    }

private:
    const Json& j_;
    std::string path_;
};

JsonError inconsistent(std::string path, std::string message) {
    return make_error(match_code::kInconsistentState, std::move(path), std::move(message));
}

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
    if (auto e = check_object(j, path, {"white", "black", "queen", "striker_penalty", "target"})) {
        return e;
    }
    Fields f(j, path);
    for (const FreestyleField& field : fields) {
        f.integer(field.name, 0, kMaxFileScore, out.*(field.member));
    }
    return f.error;
}

std::optional<int> team_or_null(Fields& f, std::string_view key, int teams) {
    if (!f.has(key) || f[key].is_null()) {
        return std::nullopt;
    }
    int team = 0;
    f.integer(key, 0, teams - 1, team);
    return team;
}

MaybeError read_board_result(const Json& j, const std::string& path, int teams,
                             rules::BoardResult& out) {
    if (auto e = check_object(j, path, {"board", "winner_team", "points", "reason"})) {
        return e;
    }
    Fields f(j, path);
    f.integer("board", 1, kMaxCount, out.board);
    out.winner_team = team_or_null(f, "winner_team", teams);
    f.integer("points", 0, kMaxFileScore, out.points);
    f.enumeration("reason", &rules::parse_rule_code, out.reason);
    return f.error;
}

MaybeError read_game_result(const Json& j, const std::string& path, int teams,
                            rules::GameResult& out) {
    if (auto e = check_object(j, path, {"winner_team", "reason"})) {
        return e;
    }
    Fields f(j, path);
    out.winner_team = team_or_null(f, "winner_team", teams);
    f.enumeration("reason", &rules::parse_rule_code, out.reason);
    return f.error;
}

// 19 bodies with ids 0..18 (any order), the queen 0, nine black and nine white, at rest.
MaybeError decode_bodies(const Json& j, const std::string& path, MatchState& s) {
    if (!j.is_array() || j.size() != static_cast<std::size_t>(kCoinCount)) {
        return make_error(scene_code::kWrongType, path,
                          path + " must be an array of the 19 pieces (ids 0..18)");
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
        return make_error(
            problem->code,
            field_path(index_path(path, static_cast<std::size_t>(index)), problem->field),
            problem->message);
    }
    s.bodies = std::move(bodies);
    return std::nullopt;
}

MaybeError decode_pocketed(const Json& j, const std::string& path, MatchState& s) {
    if (!j.is_array() || j.size() > static_cast<std::size_t>(kCoinCount)) {
        return make_error(scene_code::kWrongType, path,
                          path + " must be an array of at most 19 pieces");
    }
    s.pocketed.clear();
    const int seats = static_cast<int>(s.seats.size());
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string at = index_path(path, i);
        if (auto e = check_object(j[i], at, {"id", "seat", "turn_number"})) {
            return e;
        }
        if (auto e = require_field(j[i], "id", at)) {
            return e;
        }
        Fields f(j[i], at);
        rules::PocketedPiece p;
        f.integer("id", 0, kCoinCount - 1, p.id);
        f.integer("seat", 0, seats - 1, p.seat);
        f.integer("turn_number", 0, kMaxTurn, p.turn_number);
        if (f.error) {
            return f.error;
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
    if (auto e = check_object(j, path, {"status", "seat"})) {
        return e;
    }
    Fields f(j, path);
    f.enumeration("status", &parse_queen_status, s.queen.status);
    s.queen.seat = -1;
    f.integer("seat", -1, static_cast<int>(s.seats.size()) - 1, s.queen.seat);
    return f.error;
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

MaybeError decode_counters(Fields& f, MatchState& s) {
    const auto teams = s.scores.size();
    const int seats = static_cast<int>(s.seats.size());
    f.int_array("scores", teams, -kMaxFileScore, kMaxFileScore, s.scores);
    f.int_array("dues_owed", teams, 0, kCoinCount, s.dues_owed);
    f.int_array("missed_turns", s.seats.size(), 0, kMaxCount, s.missed_turns);
    f.integer("board", 1, kMaxCount, s.board);
    f.integer("breaker", 0, seats - 1, s.breaker);
    f.integer("turn_seat", 0, seats - 1, s.turn_seat);
    f.integer("turn_number", 0, kMaxTurn, s.turn_number);
    f.integer("strokes_this_board", 0, kMaxTurn, s.strokes_this_board);
    f.integer("break_tries", 0, s.config.break_tries - 1, s.break_tries);
    f.boolean("break_done", s.break_done);
    f.enumeration("phase", &parse_phase, s.phase);
    return f.error;
}

MaybeError decode_results(Fields& f, MatchState& s, const std::string& path) {
    const int teams = static_cast<int>(s.scores.size());
    if (f.has("boards")) {
        const Json& a = f["boards"];
        if (!a.is_array() || a.size() > static_cast<std::size_t>(kMaxCount)) {
            return make_error(scene_code::kWrongType, f.at("boards"),
                              f.at("boards") + " must be an array");
        }
        s.boards.assign(a.size(), {});
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (auto e =
                    read_board_result(a[i], index_path(f.at("boards"), i), teams, s.boards[i])) {
                return e;
            }
        }
    }
    if (f.has("result") && !f["result"].is_null()) {
        rules::GameResult result;
        if (auto e = read_game_result(f["result"], f.at("result"), teams, result)) {
            return e;
        }
        s.result = result;
    }
    if (s.result.has_value() != (s.phase == rules::Phase::GameOver)) {
        return inconsistent(field_path(path, "result"),
                            "a result is given exactly when the phase is game_over");
    }
    return std::nullopt;
}

MaybeError check_state_keys(const Json& j, const std::string& path) {
    return check_object(j, path, {"rule_set",     "rules",
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
    Decoded<rules::RulesConfig> out;
    out.value = base;
    if (auto e =
            check_object(j, path,
                         {"seat_count", "first_breaker", "shot_clock_s", "shot_clock_grace_s",
                          "missed_turns_to_lose", "target_points", "max_boards", "queen_points",
                          "queen_points_limit", "board_points_cap", "break_tries", "freestyle"})) {
        out.error = e;
        return out;
    }
    Fields f(j, path);
    for (const IntField& field : ints) {
        f.integer(field.name, field.lo, field.hi, out.value.*(field.member));
    }
    f.number("shot_clock_s", Range{0.0, 3600.0}, out.value.shot_clock_s);
    f.number("shot_clock_grace_s", Range{0.0, 3600.0}, out.value.shot_clock_grace_s);
    if (f.has("freestyle")) {
        f.error = decode_freestyle(f["freestyle"], f.at("freestyle"), out.value.freestyle);
    }
    out.error = f.error;
    if (!out.error) {
        if (auto problem = rules::validate_rules_config(out.value)) {
            out.error = make_error(scene_code::kInvalidConfig, field_path(path, problem->field),
                                   problem->message);
        }
    }
    return out;
}

Decoded<rules::MatchState> decode_match_state(const nlohmann::json& j, const std::string& path) {
    Decoded<MatchState> out;
    const auto fail = [&out](JsonError e) {
        out.error = std::move(e);
        return out;
    };
    if (auto e = check_state_keys(j, path)) {
        return fail(*e);
    }
    Fields f(j, path);
    rules::RuleSet rule_set = rules::RuleSet::Icf;
    f.enumeration("rule_set", &rules::parse_rule_set, rule_set);
    if (f.error) {
        return fail(*f.error);
    }
    rules::RulesConfig config;
    if (f.has("rules")) {
        auto decoded = decode_rules_config(f["rules"], {}, f.at("rules"));
        if (!decoded.ok()) {
            return fail(*decoded.error);
        }
        config = decoded.value;
    }
    PhysicsConfig physics;
    if (f.has("physics")) {
        auto decoded = decode_config(f["physics"], {}, f.at("physics"));
        if (!decoded.ok()) {
            return fail(*decoded.error);
        }
        physics = decoded.value;
    }
    MatchState s = rules::new_match(rule_set, config, physics);
    if (f.has("bodies")) {
        if (auto e = decode_bodies(f["bodies"], f.at("bodies"), s)) {
            return fail(*e);
        }
        derive_pocketed(s);
        if (!s.bodies[kQueenId].pocketed && rule_set != rules::RuleSet::DiscPool) {
            s.queen = {};
        }
    }
    if (f.has("pocketed")) {
        if (auto e = decode_pocketed(f["pocketed"], f.at("pocketed"), s)) {
            return fail(*e);
        }
    }
    if (f.has("queen")) {
        if (auto e = decode_queen(f["queen"], f.at("queen"), s)) {
            return fail(*e);
        }
    }
    if (auto e = decode_counters(f, s)) {
        return fail(*e);
    }
    if (auto e = decode_results(f, s, path)) {
        return fail(*e);
    }
    if (auto e = check_pieces(path, s)) {
        return fail(*e);
    }
    if (auto e = check_queen(path, s)) {
        return fail(*e);
    }
    out.value = std::move(s);
    return out;
}

Decoded<Shot> decode_rules_shot(const nlohmann::json& j, const std::string& path) {
    Decoded<Shot> out;
    if (auto e = check_object(j, path, {"x", "angle", "power"})) {
        out.error = e;
        return out;
    }
    for (std::string_view key : {"x", "angle", "power"}) {
        if (auto e = require_field(j, key, path)) {
            out.error = e;
            return out;
        }
    }
    const double big = std::numeric_limits<double>::max();
    Fields f(j, path);
    f.number("x", Range{-big, big}, out.value.x_px);
    f.number("angle", Range{-big, big}, out.value.angle_rad);
    f.number("power", Range{-big, big}, out.value.power);
    out.error = f.error;
    return out;
}

} // namespace carrom::proto
