// The golden cases of redirects (docs/protocol.md, "Redirects"): which are followed, where the
// next link goes, what hello carries there, and which are refused.
#include "session_cases.hpp"

namespace carrom::net::golden {
namespace {

const std::string kInstanceB = "ws://127.0.0.1:7801/i/b/";
const std::string kRoom = "K7M2QX";

json redirected(double t, const std::string& url, const std::string& reason,
                const std::string& code = {}, const std::string& as = {}) {
    json args{{"url", url}, {"reason", reason}};
    if (!code.empty()) {
        args["code"] = code;
    }
    if (!as.empty()) {
        args["as"] = as;
    }
    return at(t, "redirect", args);
}

// (Re)started at t and welcomed by t + 0.2, no room asked for: the lobby.
std::vector<json> in_lobby(double t) {
    return {at(t, "start"), at(t + 0.1, "link_opened"), welcome(t + 0.2, kToken)};
}

} // namespace

std::vector<Case> redirect_cases() {
    std::vector<Case> out;
    {
        Case c{"redirect_room_joins_the_named_room_there",
               "join_room answered with redirect (room): connect to its URL at once, hello "
               "without a token, join_room{code, as}; the close 4005 of the old link is no loss",
               {at(0.0, "request"), at(0.0, "start"), at(0.1, "link_opened"), welcome(0.2, kToken),
                redirected(0.3, kInstanceB, "room", kRoom, "player"), closed(0.31, 4005),
                at(0.4, "link_opened"), welcome(0.5, kOther), at(0.6, "room_state")}};
        out.push_back(c);
    }
    {
        Case c{"redirect_seat_resumes_there_within_the_same_loss",
               "a resume answered with redirect (seat): hello with the token at its URL; the "
               "loss and its tries last until the room's state",
               in_room_lost_and_retried()};
        add(c.events, {redirected(1.6, kInstanceB, "seat"), closed(1.61, 4005),
                       at(1.7, "link_opened"), welcome(1.8, kToken), at(1.9, "room_state")});
        out.push_back(c);
    }
    {
        Case c{"redirect_moved_resumes_the_seat_else_joins_the_room",
               "moved (a draining instance): hello with the token at the URL; a welcome with "
               "another token (no seat there) joins the named room instead; a spectator's "
               "hello carries no token (a spectator holds no seat) and joins the room again",
               into_room(0.0)};
        add(c.events, {redirected(1.0, kInstanceB, "moved", kRoom, "player"),
                       at(1.1, "link_opened"), welcome(1.2, kToken), at(1.3, "room_state"),
                       redirected(2.0, kAddress + "/i/c/", "moved", kRoom, "spectator"),
                       at(2.1, "link_opened"), welcome(2.2, kOther), at(2.3, "room_state")});
        out.push_back(c);
    }
    {
        Case c{"redirect_moved_after_bad_token_joins_the_room",
               "moved, and the seat is not held there (bad_token): the welcome that follows "
               "joins the named room as a new player",
               into_room(0.0)};
        add(c.events,
            {redirected(1.0, kInstanceB, "moved", kRoom, "player"), at(1.1, "link_opened"),
             error(1.2, "bad_token"), welcome(1.3, kOther), at(1.4, "room_state")});
        out.push_back(c);
    }
    out.push_back({"redirect_quick_match_joins_the_paired_room",
                   "quick_match paired on another instance: join_room{code, player} there; "
                   "carrom-bot (seat_only) follows too",
                   {at(0.0, "request"), at(0.0, "start"), at(0.1, "link_opened"),
                    welcome(0.2, kToken), redirected(3.0, kInstanceB, "quick_match", kRoom),
                    at(3.1, "link_opened"), welcome(3.2, kOther), at(3.3, "room_state")},
                   ReconnectPolicy::SeatOnly});
    {
        Case c{"redirect_to_another_host_is_refused",
               "a URL whose host is not the given address's host (or not ws/wss, or with user "
               "information) is never connected to: give up; the close 4005 changes nothing",
               {at(0.0, "request"), at(0.0, "start"), at(0.1, "link_opened"), welcome(0.2, kToken),
                redirected(0.3, "ws://127.0.0.2:7777/", "room", kRoom), closed(0.4, 4005),
                at(5.0, "tick")}};
        double t = 10.0;
        for (const char* url :
             {"ws://127.0.0.1.example:7777/", "http://127.0.0.1:7777/", "ws://evil@127.0.0.1:7801/",
              "ws://127.0.0.1@evil:7801/", "ws:/127.0.0.1:7801/", "ws://:7801/"}) {
            add(c.events, in_lobby(t));
            add(c.events, {redirected(t + 0.3, url, "room", kRoom)});
            t += 10.0;
        }
        out.push_back(c);
    }
    {
        Case c{"redirect_from_wss_never_goes_to_ws",
               "on a wss:// link only wss:// is followed; the host's case and the port and "
               "path do not matter",
               in_lobby(0.0)};
        c.address = "wss://Carrom.Example:443/play";
        add(c.events, {redirected(0.3, "ws://carrom.example/i/b/", "room", kRoom)});
        add(c.events, in_lobby(10.0));
        add(c.events, {redirected(10.3, "wss://CARROM.example:8443/i/b/", "room", kRoom),
                       at(10.4, "link_opened"), welcome(10.5, kOther), at(10.6, "room_state")});
        out.push_back(c);
    }
    {
        Case c{"redirect_from_ws_may_go_to_wss_and_ipv6",
               "ws:// may be redirected to wss:// of the same host; IPv6 hosts compare with "
               "their brackets",
               in_lobby(0.0)};
        c.address = "ws://[::1]:7777";
        add(c.events, {redirected(0.3, "wss://[::1]:7802/", "room", kRoom, "spectator"),
                       at(0.4, "link_opened"), welcome(0.5, kOther), at(0.6, "room_state"),
                       redirected(1.0, "ws://[::2]:7777/", "moved", kRoom)});
        out.push_back(c);
    }
    {
        Case c{
            "the_fourth_redirect_in_a_row_is_refused",
            "three redirects in a row are followed, the fourth is refused; the room's state "
            "starts the count again",
            {at(0.0, "request"), at(0.0, "start"), at(0.1, "link_opened"), welcome(0.2, kToken)}};
        double t = 1.0;
        for (int i = 0; i < 3; ++i) {
            add(c.events, {redirected(t, kInstanceB, "room", kRoom), at(t + 0.1, "link_opened"),
                           welcome(t + 0.2, kOther)});
            t += 1.0;
        }
        add(c.events, {at(t, "room_state")});
        for (int i = 0; i < 3; ++i) {
            t += 1.0;
            add(c.events, {redirected(t, kInstanceB, "moved", kRoom), at(t + 0.1, "link_opened"),
                           welcome(t + 0.2, kOther)});
        }
        add(c.events, {redirected(t + 1.0, kInstanceB, "room", kRoom)});
        out.push_back(c);
    }
    {
        Case c{"a_loss_after_a_redirect_tries_the_given_address",
               "a link lost on the instance a redirect named: back-off as always, and the next "
               "try goes to the address the player gave",
               into_room(0.0)};
        add(c.events, {redirected(1.0, kInstanceB, "moved", kRoom), at(1.1, "link_opened"),
                       welcome(1.2, kToken), at(1.3, "room_state"), closed(5.0)});
        add(c.events, retry(5.5));
        add(c.events, {redirected(5.6, kInstanceB, "seat"), closed(5.7, 0)});
        add(c.events, retry(6.7));
        out.push_back(c);
    }
    {
        Case c{"match_moving_is_tried_again_with_back_off",
               "match_moving then close 1013: tried again with back-off, by carrom-bot too "
               "(seat_only) before it holds a seat; the request is asked again",
               {at(0.0, "request"), at(0.0, "start"), at(0.1, "link_opened"), welcome(0.2, kToken),
                error(0.3, "match_moving"), closed(0.3, 1013)},
               ReconnectPolicy::SeatOnly};
        add(c.events, retry(0.8));
        add(c.events, {welcome(0.9, kOther), at(1.0, "room_state")});
        out.push_back(c);
    }
    out.push_back({"close_4005_without_a_redirect_is_a_loss",
                   "a close 4005 whose redirect did not arrive is a loss like any other",
                   into_room(0.0)});
    add(out.back().events, {closed(1.0, 4005)});
    add(out.back().events, retry(1.5));
    return out;
}

} // namespace carrom::net::golden
