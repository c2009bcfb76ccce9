#pragma once
// The room states the MatchModel tests start from: Ana (seat 0, bottom, white) against Ben
// (seat 1, top, black) in singles; Asha (0, bottom) and Cy (2, top) against Ravi (1, right) and
// Dee (3, left) in doubles, where a seat's score and dues are its team's.

#include "carrom/proto/server_messages.hpp"

namespace carrom::client::test {

inline proto::RoomState singles_room(int you = 0) {
    proto::RoomState r;
    r.code = "ABC234";
    r.you = you;
    r.rule_set = proto::RuleSet::Icf;
    r.seats.resize(2);
    r.seats[0] = {true, "Ana", true, false, proto::Colour::White, proto::Baseline::Bottom};
    r.seats[1] = {true, "Ben", true, false, proto::Colour::Black, proto::Baseline::Top};
    r.scores = {3, 1};
    r.dues = {0, 1};
    r.turn = 4;
    r.to_play = 0;
    r.phase = proto::Phase::Aiming;
    r.server_time_ms = 5'000'000;
    r.shot_clock_deadline_ms = 5'015'000;
    r.bodies = {{0, BodyKind::Queen, {300, 300}, {}, false},
                {1, BodyKind::Black, {300, 265}, {}, false},
                {2, BodyKind::White, {0, 0}, {}, true}};
    return r;
}

inline proto::RoomState doubles_room(int you) {
    proto::RoomState r = singles_room(you);
    r.seats.resize(4);
    r.seats[0] = {true, "Asha", true, false, proto::Colour::White, proto::Baseline::Bottom};
    r.seats[1] = {true, "Ravi", true, true, proto::Colour::Black, proto::Baseline::Right};
    r.seats[2] = {true, "Cy", true, false, proto::Colour::White, proto::Baseline::Top};
    r.seats[3] = {true, "Dee", false, false, proto::Colour::Black, proto::Baseline::Left};
    r.scores = {7, 3, 7, 3};
    r.dues = {0, 1, 0, 1};
    r.to_play = 1;
    return r;
}

} // namespace carrom::client::test
