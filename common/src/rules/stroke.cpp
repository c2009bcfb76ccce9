#include "stroke.hpp"

#include <algorithm>
#include <utility>

namespace carrom::rules::detail {

int other_team(int team) {
    return 1 - team;
}

BodyKind other_colour(BodyKind colour) {
    return colour == BodyKind::White ? BodyKind::Black : BodyKind::White;
}

const Body& piece(const MatchState& state, int id) {
    for (const Body& body : state.bodies) {
        if (body.id == id) {
            return body;
        }
    }
    return state.bodies.front(); // unreachable: every state holds ids 0..18
}

Body& piece(MatchState& state, int id) {
    return const_cast<Body&>(piece(std::as_const(state), id));
}

bool contains(const std::vector<int>& ids, int id) {
    return std::find(ids.begin(), ids.end(), id) != ids.end();
}

std::vector<int> of_kind(const Stroke& s, BodyKind kind) {
    std::vector<int> out;
    for (int id : s.in) {
        if (piece(s.state, id).kind == kind) {
            out.push_back(id);
        }
    }
    return out;
}

int count_pocketed(const MatchState& state, BodyKind kind) {
    return static_cast<int>(
        std::count_if(state.pocketed.begin(), state.pocketed.end(),
                      [kind](const PocketedPiece& p) { return p.kind == kind; }));
}

namespace {

// The body with this id (ids are unique). The engine returns bodies in input order, so the
// one at `hint` (the index in the state) is checked first.
const Body* find_body(const std::vector<Body>& bodies, int id, std::size_t hint) {
    if (hint < bodies.size() && bodies[hint].id == id) {
        return &bodies[hint];
    }
    for (const Body& body : bodies) {
        if (body.id == id) {
            return &body;
        }
    }
    return nullptr;
}

// Newly pocketed piece ids: first in pocket_order, then any others by id.
std::vector<int> newly_pocketed(const MatchState& state, const StrokePhysics& physics) {
    std::vector<int> fresh;
    for (std::size_t i = 0; i < state.bodies.size(); ++i) {
        const Body& before = state.bodies[i];
        const Body* after = find_body(physics.bodies, before.id, i);
        if (!before.pocketed && after != nullptr && after->pocketed) {
            fresh.push_back(before.id);
        }
    }
    std::vector<int> ordered;
    for (int id : physics.pocket_order) {
        if (contains(fresh, id) && !contains(ordered, id)) {
            ordered.push_back(id);
        }
    }
    for (int id : fresh) {
        if (!contains(ordered, id)) {
            ordered.push_back(id);
        }
    }
    return ordered;
}

// The engine may leave a body resting on a cushion a rounding error outside the range that
// validate_scene accepts; the rules keep every state valid for the next stroke.
Vec2 inside_cushions(const PhysicsConfig& physics, BodyKind kind, Vec2 pos) {
    const double lo = physics.cushion_min(physics.radius(kind));
    const double hi = physics.cushion_max(physics.radius(kind));
    return {std::clamp(pos.x, lo, hi), std::clamp(pos.y, lo, hi)};
}

} // namespace

Stroke begin_stroke(const MatchState& state, int seat, const Shot& shot,
                    const StrokePhysics& physics) {
    Stroke s;
    s.state = state;
    s.seat = seat;
    s.team = team_of(state, seat);
    s.in = newly_pocketed(state, physics);
    s.foul = physics.striker_pocketed;
    s.touched = physics.striker_touched_coin;
    s.cover_stroke = state.queen.status == QueenStatus::PendingCover && state.queen.seat == seat;
    s.scores_before = state.scores;
    for (std::size_t i = 0; i < s.state.bodies.size(); ++i) {
        Body& body = s.state.bodies[i];
        const Body* after = find_body(physics.bodies, body.id, i);
        if (after != nullptr && !body.pocketed) {
            body.pos_px = inside_cushions(state.physics, body.kind, after->pos_px);
        }
        body.vel_px_s = {};
    }
    for (int id : s.in) {
        Body& body = piece(s.state, id);
        body.pocketed = true;
        s.state.pocketed.push_back(PocketedPiece{id, body.kind, seat, state.turn_number});
    }
    s.state.missed_turns[static_cast<std::size_t>(seat)] = 0;
    s.state.strokes_this_board += 1;
    ShotOutcome& o = s.outcome;
    o.seat = seat;
    o.turn_number = state.turn_number;
    o.shot_taken = true;
    o.shot = shot;
    o.pocketed = s.in;
    o.striker_pocketed = physics.striker_pocketed;
    o.queen_before = state.queen;
    return s;
}

namespace {

// Puts the pieces returned this stroke on the board: the queen first, so that it takes the centre
// (../shared/reference/carrom-rules.md), then the others in the order they were returned, each on
// the free spot nearest the centre among the pieces already there.
void place_returned(Stroke& s) {
    MatchState& st = s.state;
    std::vector<ReturnedPiece>& returned = s.outcome.returned;
    for (const ReturnedPiece& back : returned) {
        piece(st, back.id).pocketed = true; // not yet placed: no obstacle for the others
    }
    for (const bool queen : {true, false}) {
        for (ReturnedPiece& back : returned) {
            if ((back.id == kQueenId) != queen) {
                continue;
            }
            Body& body = piece(st, back.id);
            body.pos_px =
                free_spot_near_centre(st.physics, st.bodies, st.physics.radius(body.kind));
            body.pocketed = false;
            back.pos_px = body.pos_px;
        }
    }
}

} // namespace

StrokeResult finish_stroke(Stroke& s, bool extra_stroke) {
    place_returned(s);
    MatchState& st = s.state;
    ShotOutcome& o = s.outcome;
    o.score_changes.clear();
    for (std::size_t t = 0; t < st.scores.size(); ++t) {
        o.score_changes.push_back(st.scores[t] - s.scores_before[t]);
    }
    o.queen_after = st.queen;
    o.dues_owed = st.dues_owed[static_cast<std::size_t>(s.team)];
    const int seats = st.config.seat_count;
    int next = s.seat;
    if (st.phase == Phase::AwaitingShot) {
        next = extra_stroke ? s.seat : next_seat(s.seat, seats);
        o.extra_stroke = extra_stroke;
    } else if (st.phase == Phase::BoardOver) {
        next = next_seat(st.breaker, seats);
    }
    if (next != s.seat) {
        st.break_tries = 0;
    }
    st.turn_seat = next;
    o.next_seat = next;
    st.turn_number += 1;
    return StrokeResult{std::move(s.state), std::move(s.outcome)};
}

void return_piece(Stroke& s, int id, RuleCode reason) {
    MatchState& st = s.state;
    auto it = std::find_if(st.pocketed.begin(), st.pocketed.end(),
                           [id](const PocketedPiece& p) { return p.id == id; });
    if (it != st.pocketed.end()) {
        st.pocketed.erase(it);
    }
    Body& body = piece(st, id);
    body.vel_px_s = {};
    body.pocketed = false; // back in play at once; its spot is chosen by place_returned
    s.outcome.returned.push_back(ReturnedPiece{id, body.kind, body.pos_px, reason});
}

void return_queen(Stroke& s, RuleCode reason) {
    if (piece(s.state, kQueenId).pocketed) {
        return_piece(s, kQueenId, reason);
    }
    s.state.queen = QueenState{QueenStatus::OnBoard, -1};
}

void cover_queen(Stroke& s) {
    s.state.queen = QueenState{QueenStatus::Covered, s.seat};
}

void add_foul(Stroke& s, RuleCode code) {
    s.outcome.fouls.push_back(Foul{code, s.seat});
}

void pay_dues(Stroke& s, BodyKind colour) {
    int& owed = s.state.dues_owed[static_cast<std::size_t>(s.team)];
    while (owed > 0) {
        const auto& list = s.state.pocketed;
        auto it = std::find_if(list.rbegin(), list.rend(),
                               [colour](const PocketedPiece& p) { return p.kind == colour; });
        if (it == list.rend()) {
            return;
        }
        return_piece(s, it->id, RuleCode::DuePaid);
        owed -= 1;
        s.outcome.dues_paid += 1;
    }
}

void end_game(MatchState& state, ShotOutcome& outcome, std::optional<int> winner_team,
              RuleCode reason) {
    state.phase = Phase::GameOver;
    state.result = GameResult{winner_team, reason};
    outcome.game_end = state.result;
}

namespace {

std::optional<int> leader(const MatchState& state) {
    if (state.scores[0] == state.scores[1]) {
        return std::nullopt;
    }
    return state.scores[0] > state.scores[1] ? 0 : 1;
}

} // namespace

void end_board(Stroke& s, std::optional<int> winner_team, int points, RuleCode reason) {
    MatchState& st = s.state;
    if (winner_team) {
        st.scores[static_cast<std::size_t>(*winner_team)] += points;
    }
    const BoardResult board{st.board, winner_team, points, reason};
    st.boards.push_back(board);
    s.outcome.board_end = board;
    st.phase = Phase::BoardOver;
    if (st.rule_set != RuleSet::Icf) {
        end_game(st, s.outcome, winner_team, reason);
        return;
    }
    const std::optional<int> lead = leader(st);
    if (lead && st.scores[static_cast<std::size_t>(*lead)] >= st.config.target_points) {
        end_game(st, s.outcome, lead, RuleCode::TargetPoints);
    } else if (lead && st.board >= st.config.max_boards) {
        end_game(st, s.outcome, lead, RuleCode::BoardsPlayed);
    }
}

} // namespace carrom::rules::detail
