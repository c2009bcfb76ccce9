// Encoding of the rules engine's data (see match_json.hpp).

#include "carrom/proto/match_json.hpp"

namespace carrom::proto {
namespace {

using Json = nlohmann::json;

Json optional_team(const std::optional<int>& team) {
    return team ? Json(*team) : Json(nullptr);
}

Json seats_to_json(const std::vector<rules::Seat>& seats) {
    Json out = Json::array();
    for (const rules::Seat& seat : seats) {
        out.push_back({{"index", seat.index},
                       {"side", std::string(to_string(seat.side))},
                       {"team", seat.team},
                       {"partner", seat.partner}});
    }
    return out;
}

Json pocketed_to_json(const std::vector<rules::PocketedPiece>& pocketed) {
    Json out = Json::array();
    for (const rules::PocketedPiece& p : pocketed) {
        out.push_back({{"id", p.id}, {"seat", p.seat}, {"turn_number", p.turn_number}});
    }
    return out;
}

Json fouls_to_json(const std::vector<rules::Foul>& fouls) {
    Json out = Json::array();
    for (const rules::Foul& foul : fouls) {
        out.push_back({{"code", std::string(to_string(foul.code))}, {"seat", foul.seat}});
    }
    return out;
}

Json returned_to_json(const std::vector<rules::ReturnedPiece>& returned) {
    Json out = Json::array();
    for (const rules::ReturnedPiece& r : returned) {
        out.push_back({{"id", r.id},
                       {"kind", std::string(to_string(r.kind))},
                       {"pos", vec_to_json(r.pos_px)},
                       {"reason", std::string(to_string(r.reason))}});
    }
    return out;
}

} // namespace

std::string_view to_string(rules::Phase phase) {
    return enum_names::name_or_unknown(kMatchPhaseNames, phase);
}
bool parse_phase(std::string_view text, rules::Phase& out) {
    return enum_names::parse_into(kMatchPhaseNames, text, out);
}
std::string_view to_string(rules::QueenStatus status) {
    return enum_names::name_or_unknown(kQueenStatusNames, status);
}
bool parse_queen_status(std::string_view text, rules::QueenStatus& out) {
    return enum_names::parse_into(kQueenStatusNames, text, out);
}

Json rules_config_to_json(const rules::RulesConfig& c) {
    return {{"seat_count", c.seat_count},
            {"first_breaker", c.first_breaker},
            {"shot_clock_s", c.shot_clock_s},
            {"shot_clock_grace_s", c.shot_clock_grace_s},
            {"missed_turns_to_lose", c.missed_turns_to_lose},
            {"target_points", c.target_points},
            {"max_boards", c.max_boards},
            {"queen_points", c.queen_points},
            {"queen_points_limit", c.queen_points_limit},
            {"board_points_cap", c.board_points_cap},
            {"break_tries", c.break_tries},
            {"freestyle",
             {{"white", c.freestyle.white},
              {"black", c.freestyle.black},
              {"queen", c.freestyle.queen},
              {"striker_penalty", c.freestyle.striker_penalty},
              {"target", c.freestyle.target}}}};
}

Json queen_state_to_json(const rules::QueenState& queen) {
    return {{"status", std::string(to_string(queen.status))}, {"seat", queen.seat}};
}

Json board_result_to_json(const rules::BoardResult& board) {
    return {{"board", board.board},
            {"winner_team", optional_team(board.winner_team)},
            {"points", board.points},
            {"reason", std::string(to_string(board.reason))}};
}

Json game_result_to_json(const rules::GameResult& result) {
    return {{"winner_team", optional_team(result.winner_team)},
            {"reason", std::string(to_string(result.reason))}};
}

Json rules_shot_to_json(const Shot& shot) {
    return {{"x", shot.x_px}, {"angle", shot.angle_rad}, {"power", shot.power}};
}

Json match_state_to_json(const rules::MatchState& s) {
    Json boards = Json::array();
    for (const rules::BoardResult& board : s.boards) {
        boards.push_back(board_result_to_json(board));
    }
    return {{"rule_set", std::string(to_string(s.rule_set))},
            {"rules", rules_config_to_json(s.config)},
            {"physics", config_overrides_to_json(s.physics)},
            {"seats", seats_to_json(s.seats)},
            {"bodies", bodies_to_json(s.bodies)},
            {"pocketed", pocketed_to_json(s.pocketed)},
            {"scores", s.scores},
            {"dues_owed", s.dues_owed},
            {"missed_turns", s.missed_turns},
            {"board", s.board},
            {"breaker", s.breaker},
            {"turn_seat", s.turn_seat},
            {"turn_number", s.turn_number},
            {"strokes_this_board", s.strokes_this_board},
            {"break_tries", s.break_tries},
            {"break_done", s.break_done},
            {"queen", queen_state_to_json(s.queen)},
            {"phase", std::string(to_string(s.phase))},
            {"boards", boards},
            {"result", s.result ? game_result_to_json(*s.result) : Json(nullptr)}};
}

Json shot_outcome_to_json(const rules::ShotOutcome& o, bool include_physics) {
    Json out = {
        {"seat", o.seat},
        {"turn_number", o.turn_number},
        {"shot_taken", o.shot_taken},
        {"shot", o.shot_taken ? rules_shot_to_json(o.shot) : Json(nullptr)},
        {"pocketed", o.pocketed},
        {"striker_pocketed", o.striker_pocketed},
        {"fouls", fouls_to_json(o.fouls)},
        {"returned", returned_to_json(o.returned)},
        {"dues", {{"incurred", o.dues_incurred}, {"paid", o.dues_paid}, {"owed", o.dues_owed}}},
        {"queen",
         {{"before", queen_state_to_json(o.queen_before)},
          {"after", queen_state_to_json(o.queen_after)}}},
        {"score_changes", o.score_changes},
        {"extra_stroke", o.extra_stroke},
        {"next_seat", o.next_seat},
        {"board_end", o.board_end ? board_result_to_json(*o.board_end) : Json(nullptr)},
        {"game_end", o.game_end ? game_result_to_json(*o.game_end) : Json(nullptr)}};
    if (include_physics) {
        out["physics"] = o.shot_taken ? sim_result_to_json(o.physics) : Json(nullptr);
    }
    return out;
}

} // namespace carrom::proto
