// `carrom-sim --rules`: answers a rule question from the command line. Reads one JSON document
//   {"state"?: <match state>, "action"?: "shot" | "clock_expired" | "forfeit" | "next_board",
//    "seat"?: n, "shot"?: {"x", "angle", "power"}, "include_physics"?: bool}
// and prints {"outcome": <shot outcome>, "state": <state after>} (docs/rules.md). Bad input or a
// move the rules refuse prints {"error": {"code", "path", "message"}} on err and returns 2.

#include "rules_mode.hpp"

#include "carrom/proto/match_json.hpp"
#include "carrom/rules/match.hpp"

#include <iostream>
#include <string>

namespace carrom {
namespace {

using Json = nlohmann::json;

struct Request {
    rules::MatchState state;
    std::string action = "shot";
    int seat = 0;
    Shot shot;
    bool include_physics = false;
};

proto::Error bad(std::string_view code, std::string path, std::string message) {
    return proto::Error{std::string(code), std::move(message), std::move(path)};
}

std::optional<proto::Error> read_options(const Json& j, Request& r) {
    if (j.contains("action")) {
        const Json& a = j["action"];
        if (!a.is_string() ||
            (a != "shot" && a != "clock_expired" && a != "forfeit" && a != "next_board")) {
            return bad(proto::scene_code::kBadValue, "action",
                       "action must be \"shot\", \"clock_expired\", \"forfeit\" or "
                       "\"next_board\"");
        }
        r.action = a.get<std::string>();
    }
    r.seat = r.state.turn_seat;
    if (j.contains("seat")) {
        const Json& s = j["seat"];
        const int seats = static_cast<int>(r.state.seats.size());
        if (!s.is_number_integer() || s.get<std::int64_t>() < 0 || s.get<std::int64_t>() >= seats) {
            return bad(proto::scene_code::kOutOfRange, "seat",
                       "seat must be an integer in [0, " + std::to_string(seats - 1) + "]");
        }
        r.seat = s.get<int>();
    }
    if (j.contains("include_physics")) {
        if (!j["include_physics"].is_boolean()) {
            return bad(proto::scene_code::kWrongType, "include_physics",
                       "include_physics must be true or false");
        }
        r.include_physics = j["include_physics"].get<bool>();
    }
    return std::nullopt;
}

std::optional<proto::Error> read_request(std::string_view text, Request& r) {
    auto parsed = proto::parse_json_text(text);
    if (!parsed.ok()) {
        return parsed.error;
    }
    const Json& j = parsed.value;
    if (!j.is_object()) {
        return bad(proto::scene_code::kWrongType, "", "the input must be a JSON object");
    }
    for (const auto& item : j.items()) {
        const std::string& key = item.key();
        if (key != "state" && key != "action" && key != "seat" && key != "shot" &&
            key != "include_physics") {
            return bad(proto::scene_code::kUnknownField, key, "unknown field '" + key + "'");
        }
    }
    auto state = proto::decode_match_state(j.contains("state") ? j["state"] : Json::object());
    if (!state.ok()) {
        return state.error;
    }
    r.state = std::move(state.value);
    if (auto e = read_options(j, r)) {
        return e;
    }
    if (r.action == "shot") {
        if (!j.contains("shot")) {
            return bad(proto::scene_code::kMissingField, "shot", "a shot needs the field 'shot'");
        }
        auto shot = proto::decode_rules_shot(j["shot"]);
        if (!shot.ok()) {
            return shot.error;
        }
        r.shot = shot.value;
    }
    return std::nullopt;
}

rules::PlayResult run(const Request& r) {
    if (r.action == "clock_expired") {
        return rules::shot_clock_expired(r.state, r.seat);
    }
    if (r.action == "forfeit") {
        return rules::forfeit(r.state, r.seat);
    }
    if (r.action == "next_board") {
        rules::PlayResult out;
        if (r.state.phase != rules::Phase::BoardOver) {
            out.error = rules::RuleError{rules::RuleErrorCode::WrongPhase, "action",
                                         "next_board needs a state whose phase is board_over."};
        }
        out.state = rules::start_next_board(r.state);
        out.outcome.seat = r.state.turn_seat;
        out.outcome.turn_number = r.state.turn_number;
        out.outcome.queen_before = r.state.queen;
        out.outcome.queen_after = out.state.queen;
        out.outcome.score_changes.assign(r.state.scores.size(), 0);
        out.outcome.next_seat = out.state.turn_seat;
        return out;
    }
    ExactEngine engine(r.state.physics);
    return rules::play_shot(r.state, r.seat, r.shot, engine);
}

} // namespace

int run_rules_mode(std::istream& in, std::ostream& out, std::ostream& err) {
    std::string text;
    char buffer[4096];
    while (in && text.size() <= proto::kMaxSceneBytes) {
        in.read(buffer, sizeof buffer);
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
    }
    Request request;
    if (auto e = read_request(text, request)) {
        err << proto::error_to_json(*e).dump() << '\n';
        return 2;
    }
    const rules::PlayResult result = run(request);
    if (result.error) {
        err << proto::error_to_json(bad(rules::to_string(result.error->code), result.error->field,
                                        result.error->message))
                   .dump()
            << '\n';
        return 2;
    }
    const Json doc = {
        {"outcome", proto::shot_outcome_to_json(result.outcome, request.include_physics)},
        {"state", proto::match_state_to_json(result.state)}};
    out << doc.dump(2) << '\n';
    return 0;
}

} // namespace carrom
