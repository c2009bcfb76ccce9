// carrom-session-golden DIR: writes the session golden cases (DIR/NAME.json, one per case) from
// net::SessionCore: each case's events, with the actions and the state the core answered.
// tests/net/session_golden_test.cpp and tests/web/session_test.mjs replay them against the C++
// core and the web client's port. Regenerate after a deliberate change of the rules
// (tests/golden/README.md); the web port must then follow.
#include "session_cases.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace carrom::net::golden;
using carrom::net::BackoffSettings;
using carrom::net::ReconnectPolicy;

std::vector<Case> cases() {
    std::vector<Case> out;
    out.push_back({"hello_then_room_request",
                   "hello once the link opens, the room request once welcomed, then the room",
                   into_room(0.0)});
    out.push_back({"lobby_waits_for_a_choice",
                   "welcomed without a request: the lobby; the request is sent when made",
                   {at(0.0, "start"), at(0.1, "link_opened"), welcome(0.2, kToken),
                    at(5.0, "request"), at(5.1, "room_state")}});
    {
        Case c{"refusals_go_back_to_the_lobby",
               "each refusal of a room request goes back to the lobby; other errors do not",
               {at(0.0, "start"), at(0.1, "link_opened"), welcome(0.2, kToken)}};
        double t = 1.0;
        for (const char* code : {"room_not_found", "room_full", "unsupported", "too_many_rooms",
                                 "bad_field", "already_in_room"}) {
            add(c.events, {at(t, "request"), error(t + 0.1, code)});
            t += 1.0;
        }
        add(c.events,
            {at(t, "request"), error(t + 0.1, "rate_limited"), error(t + 0.2, "idle_timeout"),
             error(t + 0.3, "bad_token"), at(t + 0.4, "room_state"), error(t + 0.5, "room_full")});
        out.push_back(c);
    }
    {
        Case c{"resume_after_a_drop",
               "a link lost in a room: wait 0.5 s, then hello with the token; the room's state "
               "gives the seat back",
               into_room(0.0)};
        add(c.events, {closed(10.0), at(10.4, "tick"), at(10.5, "tick"), at(10.6, "link_opened"),
                       welcome(10.7, kToken), at(10.8, "room_state"), closed(20.0)});
        out.push_back(c);
    }
    {
        Case c{"backoff_doubles_to_the_cap_and_gives_up",
               "refused tries: 0.5 s doubling to 5 s; the last try at 130 s after the loss, "
               "then give up",
               into_room(0.0)};
        double t = 1.0;
        double wait = 0.5;
        add(c.events, {closed(t)});
        for (int i = 0; i < 40 && t < 131.0; ++i) {
            t += wait;
            add(c.events, {at(t, "tick"), closed(t, 0)});
            wait = std::min(wait * 2.0, 5.0);
            if (t + wait > 131.0) {
                wait = 131.0 - t;
            }
        }
        add(c.events, {at(t + 1.0, "tick")});
        out.push_back(c);
    }
    {
        Case c{"jitter_draws_each_delay_in_its_upper_half",
               "the caller's draw in [0, 1] places each delay d in [d/2, d]; draws outside are "
               "clamped",
               into_room(0.0)};
        double t = 1.0;
        for (const double jitter : {0.0, 0.25, 0.5, 0.999, 1.0, -0.5, 1.5}) {
            add(c.events, {closed(t, 0, jitter), at(t + 5.0, "tick")});
            t += 5.0;
        }
        out.push_back(c);
    }
    {
        Case c{"unknown_token_loses_the_seat",
               "bad_token before the welcome: the seat is gone; the welcome that follows is a new "
               "player's, in the lobby with no request",
               in_room_lost_and_retried()};
        add(c.events, {error(1.6, "bad_token"), welcome(1.7, kOther), at(1.8, "room_state"),
                       at(2.0, "request")});
        out.push_back(c);
    }
    {
        Case c{"closed_room_loses_the_seat_after_the_welcome",
               "the token is known but its room has closed: welcome, then bad_token",
               in_room_lost_and_retried()};
        add(c.events, {welcome(1.6, kToken), error(1.7, "bad_token"), closed(1.8)});
        add(c.events, retry(2.3));
        out.push_back(c);
    }
    {
        Case c{"resume_welcomed_with_another_token_loses_the_seat",
               "a welcome with another token after a resume: a new player",
               in_room_lost_and_retried()};
        add(c.events, {welcome(1.6, kOther), at(1.7, "room_state")});
        out.push_back(c);
    }
    out.push_back({"version_mismatch_ends_the_session",
                   "version_mismatch: give up; the close 4001 that follows changes nothing",
                   {at(0.0, "request"), at(0.0, "start"), at(0.1, "link_opened"),
                    error(0.2, "version_mismatch"), closed(0.3, 4001), at(5.0, "tick"),
                    welcome(5.1, kToken)}});
    {
        Case c{"final_close_codes_and_replaced",
               "close 4002 (replaced) and 4001 (version mismatch) end the session, and so does "
               "the error replaced; start() begins again",
               into_room(0.0)};
        add(c.events, {closed(1.0, 4002), at(2.0, "tick"), at(3.0, "start")});
        add(c.events, {at(3.1, "link_opened"), welcome(3.2, kToken), closed(3.3, 4001),
                       at(4.0, "start", {{"resume_token", kToken}}), at(4.1, "link_opened"),
                       welcome(4.2, kToken), at(4.3, "room_state"), error(4.4, "replaced"),
                       closed(4.5, 4002)});
        out.push_back(c);
    }
    {
        Case c{"restart_idle_timeout_and_slow_links_are_tried_again",
               "shutting_down and close 1012, idle_timeout and close 1008, close 4003 and 1013: "
               "losses tried again; a loss lasts until the room's state is back",
               into_room(0.0)};
        add(c.events, {error(1.0, "shutting_down"), closed(1.0, 1012)});
        add(c.events, retry(1.5));
        add(c.events, {welcome(1.6, kToken), error(2.0, "idle_timeout"), closed(2.0, 1008)});
        add(c.events, retry(3.0));
        add(c.events, {closed(3.1, 1013)});
        add(c.events, retry(5.1));
        add(c.events, {welcome(5.2, kToken), at(5.3, "room_state"), closed(9.0, 4003)});
        add(c.events, retry(9.5));
        out.push_back(c);
    }
    {
        Case c{"seat_only_resumes_a_seat",
               "carrom-bot: a link lost in a room is resumed, a loss during the resume too",
               in_room_lost_and_retried(), ReconnectPolicy::SeatOnly};
        add(c.events, {closed(1.6, 0)});
        add(c.events, retry(2.6));
        add(c.events, {welcome(2.7, kToken), at(2.8, "room_state")});
        out.push_back(c);
    }
    out.push_back({"seat_only_gives_up_without_a_seat",
                   "carrom-bot: a refused first connection, and a loss before the room, end it",
                   {at(0.0, "request"), at(0.0, "start"), closed(0.1, 0), at(1.0, "start"),
                    at(1.1, "link_opened"), welcome(1.2, kToken), closed(1.3)},
                   ReconnectPolicy::SeatOnly});
    {
        Case c{"seat_only_resume_of_the_callers_own",
               "carrom-bot's resume() after its own drop: hello with the token even before a "
               "room; bad_token ends it",
               {at(0.0, "request"), at(0.0, "start"), at(0.1, "link_opened"), welcome(0.2, kToken),
                at(1.0, "start", {{"resume_token", kToken}}), at(1.1, "link_opened"),
                error(1.2, "bad_token")},
               ReconnectPolicy::SeatOnly};
        out.push_back(c);
    }
    {
        Case c{"never_gives_up_at_the_first_loss", "carrom-bot --resume-for 0", into_room(0.0),
               ReconnectPolicy::Never};
        add(c.events, {closed(1.0, 1012)});
        out.push_back(c);
    }
    {
        Case c{"lost_while_joining_asks_again_as_a_new_player",
               "a request not yet answered is no seat: the new link says hello without the token "
               "and asks again",
               {at(0.0, "request"), at(0.0, "start"), at(0.1, "link_opened"), welcome(0.2, kToken),
                closed(30.0)}};
        add(c.events, retry(30.5));
        add(c.events, {welcome(30.6, kOther), at(31.0, "room_state")});
        out.push_back(c);
    }
    {
        Case c{"leave_then_choose_again",
               "leave: the lobby; a late room state is not ours; a loss in the lobby says hello "
               "again without the token; a request made while away is sent once welcomed",
               into_room(0.0)};
        add(c.events, {at(1.0, "leave"), at(1.1, "room_state"), at(1.2, "leave"),
                       at(2.0, "request"), at(2.1, "room_state"), at(3.0, "leave"), closed(4.0)});
        add(c.events, {at(4.2, "request")});
        add(c.events, retry(4.5));
        add(c.events, {welcome(4.6, kOther), at(4.7, "room_state")});
        out.push_back(c);
    }
    {
        Case c{"a_loss_lasts_until_the_seat_is_back",
               "a resume welcomed and lost before the room's state goes on with the same loss",
               in_room_lost_and_retried()};
        add(c.events, {welcome(1.6, kToken), closed(1.7)});
        add(c.events, retry(2.7));
        add(c.events, {welcome(2.8, kToken), at(2.9, "room_state"), closed(10.0)});
        out.push_back(c);
    }
    out.push_back({"reload_resumes_with_the_stored_token",
                   "start with a token (a reload of the web page): hello with it, the seat back",
                   {at(0.0, "start", {{"resume_token", kToken}}), at(0.1, "link_opened"),
                    welcome(0.2, kToken), at(0.3, "room_state")}});
    out.push_back(
        {"refused_connects_before_a_welcome_stay_connecting",
         "before any welcome a loss is tried again in the phase connecting",
         {at(0.0, "request"), at(0.0, "start"), closed(0.1, 0), at(0.6, "tick"), closed(0.7, 0),
          at(1.7, "tick"), at(1.8, "link_opened"), welcome(1.9, kToken)}});
    {
        Case c{"the_last_try_is_at_the_give_up_time",
               "with 1 s doubling and 4 s to give up: tries at 1 s, 3 s and 4 s, then give up; "
               "start() begins again",
               into_room(0.0), ReconnectPolicy::Always, BackoffSettings{1.0, 5.0, 4.0}};
        add(c.events, {closed(10.0), at(11.0, "tick"), closed(11.0, 0), at(13.0, "tick"),
                       closed(13.0, 0), at(14.0, "tick"), closed(14.0, 0), at(20.0, "tick"),
                       at(21.0, "start"), at(21.1, "link_opened")});
        out.push_back(c);
    }
    for (Case& c : redirect_cases()) {
        out.push_back(std::move(c));
    }
    return out;
}

// One step per line, in the order time, event, its arguments, actions, state.
std::string step_line(const json& event, const json& answer) {
    nlohmann::ordered_json line;
    line["t"] = event.at("t");
    line["event"] = event.at("event");
    for (auto it = event.begin(); it != event.end(); ++it) {
        if (it.key() != "t" && it.key() != "event") {
            line[it.key()] = it.value();
        }
    }
    line["actions"] = answer.at("actions");
    line["state"] = answer.at("state");
    return line.dump();
}

std::string case_text(const Case& c) {
    const json backoff{{"first_s", c.backoff.first_s},
                       {"cap_s", c.backoff.cap_s},
                       {"give_up_after_s", c.backoff.give_up_after_s}};
    const std::string policy = carrom::net::golden::policy_name(c.policy);
    json head{{"address", c.address}, {"backoff", backoff}, {"policy", policy}};
    carrom::net::SessionCore core = carrom::net::golden::core_for(head);
    std::string text =
        "{\n \"name\": " + json(c.name).dump() + ",\n \"about\": " + json(c.about).dump() +
        ",\n \"address\": " + json(c.address).dump() + ",\n \"policy\": " + json(policy).dump() +
        ",\n \"backoff\": " + backoff.dump() + ",\n \"steps\": [\n";
    for (std::size_t i = 0; i < c.events.size(); ++i) {
        const json answer = carrom::net::golden::play(core, c.events[i]);
        text += "  " + step_line(c.events[i], answer) + (i + 1 < c.events.size() ? ",\n" : "\n");
    }
    return text + " ]\n}\n";
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: carrom-session-golden DIR (tests/golden/session)\n";
        return 2;
    }
    const std::string dir = argv[1];
    for (const Case& c : cases()) {
        const std::string path = dir + "/" + c.name + ".json";
        std::ofstream file(path);
        file << case_text(c);
        if (!file) {
            std::cerr << "cannot write " << path << "\n";
            return 1;
        }
        std::cout << path << ": " << c.events.size() << " events\n";
    }
    return 0;
}
