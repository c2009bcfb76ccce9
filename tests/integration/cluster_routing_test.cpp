// Rooms across the cluster (docs/cluster.md, "Rooms across the cluster"; docs/protocol.md,
// "Redirects"): two carrom-server instances a and b on one PostgreSQL of the test's own, each with
// its real address as --public-url, and raw clients of the test. Room codes are reserved in the
// database; a join or a resume on the instance that does not run the room gets `redirect` (a
// client that follows them) or an error naming the owner's URL; quick match pairs players of two
// instances; SIGTERM on an instance hands its match to the other and sends its players there.
#include "harness.hpp"

#include "support/loopback_port.hpp"
#include "support/postgres_instance.hpp"
#include "support/server_process.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <thread>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;

// Instance `id` of the cluster on data, at ws://127.0.0.1:PORT (its --public-url), 2 s lease.
std::unique_ptr<test_support::ServerProcess>
start_routed_instance(const std::string& data, const std::string& id,
                      const std::vector<std::string>& more_args = {}) {
    test_support::ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.data = data;
    options.port = test_support::unused_loopback_port();
    options.args = {"--instance-id", id,
                    "--lease",       "2",
                    "--public-url",  "ws://127.0.0.1:" + std::to_string(options.port),
                    "--log-level",   "info"};
    options.args.insert(options.args.end(), more_args.begin(), more_args.end());
    return std::make_unique<test_support::ServerProcess>(options);
}

// hello with follows_redirects (or without), and its welcome.
proto::Welcome say_hello(ManualClient& client, bool follows_redirects,
                         std::optional<std::string> token = std::nullopt,
                         const std::string& name = "tester") {
    proto::Hello hello{proto::kProtocolVersion, name, std::move(token)};
    hello.follows_redirects = follows_redirects;
    client.send(hello);
    return client.next<proto::Welcome>().value_or(proto::Welcome{});
}

// hello with a player key (follows redirects) and its welcome.
proto::Welcome say_hello_as(ManualClient& client, const std::string& name, const std::string& key) {
    proto::Hello hello{proto::kProtocolVersion, name, std::nullopt, key, true};
    client.send(hello);
    return client.next<proto::Welcome>().value_or(proto::Welcome{});
}

// A quick-match player redirected to its partner's instance, greeted there by greet: seat 1, and
// the match begins.
void expect_seated_there(const proto::Redirect& redirect,
                         const std::function<void(ManualClient&)>& greet) {
    ManualClient moved(redirect.url, "first");
    greet(moved);
    moved.send(proto::JoinRoom{redirect.code, redirect.as});
    const auto seated = moved.next<proto::RoomState>();
    ASSERT_TRUE(seated.has_value());
    EXPECT_EQ(seated->you, 1);
    EXPECT_TRUE(moved.next_event<proto::TurnEvent>().has_value());
}

// Milliseconds of the day of a log line "[YYYY-MM-DD HH:MM:SS.mmm] ..." (-1 if it has none).
double log_time_ms(const std::string& line) {
    const auto open = line.find('[');
    int h = 0, m = 0, s = 0, ms = 0;
    if (open == std::string::npos ||
        std::sscanf(line.c_str() + open, "[%*d-%*d-%*d %d:%d:%d.%d]", &h, &m, &s, &ms) != 4) {
        return -1.0;
    }
    return ((h * 60.0 + m) * 60.0 + s) * 1000.0 + ms;
}

class ClusterRouting : public ::testing::Test {
protected:
    void SetUp() override {
        a = start_routed_instance(url, "a");
        b = start_routed_instance(url, "b");
        ASSERT_NE(a->port(), 0) << a->log();
        ASSERT_NE(b->port(), 0) << b->log();
    }
    std::string query(const std::string& sql) const { return postgres.sql(database, sql).out; }
    // Polls sql until it prints want, up to 5 s; what it printed last.
    std::string query_until(const std::string& sql, const std::string& want) const {
        std::string out = query(sql);
        for (int i = 0; i < 50 && out != want; ++i) {
            std::this_thread::sleep_for(100ms);
            out = query(sql);
        }
        return out;
    }

    test_support::PostgresInstance postgres;
    std::string database = postgres.create_database();
    std::string url = postgres.url(database);
    std::unique_ptr<test_support::ServerProcess> a;
    std::unique_ptr<test_support::ServerProcess> b;
};

// A started singles match on instance `server`: the creator and the joiner, both seated.
struct StartedMatch {
    std::unique_ptr<ManualClient> creator;
    std::unique_ptr<ManualClient> joiner;
    std::string code;
    std::string creator_token;
};

StartedMatch start_match(const std::string& server_url) {
    StartedMatch m;
    m.creator = std::make_unique<ManualClient>(server_url, "creator");
    m.creator_token = say_hello(*m.creator, true, std::nullopt, "creator").resume_token;
    m.creator->send(proto::CreateRoom{});
    m.code = m.creator->next<proto::RoomState>().value_or(proto::RoomState{}).code;
    m.joiner = std::make_unique<ManualClient>(server_url, "joiner");
    say_hello(*m.joiner, true);
    m.joiner->send(proto::JoinRoom{m.code, proto::Role::Player});
    (void)m.creator->next_event<proto::TurnEvent>();
    return m;
}

TEST_F(ClusterRouting, RoomCodesAreReservedInTheDatabaseForTheInstanceThatRunsTheRoom) {
    ManualClient client(a->url());
    say_hello(client, true);
    client.send(proto::CreateRoom{});
    const auto state = client.next<proto::RoomState>();
    ASSERT_TRUE(state.has_value());
    EXPECT_EQ(query("SELECT instance_id FROM rooms WHERE code = '" + state->code + "'"), "a\n");
    // Each instance keeps codes reserved for its next rooms, none of them shared.
    EXPECT_EQ(query("SELECT count(*) FROM (SELECT code FROM rooms GROUP BY code HAVING "
                    "count(*) > 1) d"),
              "0\n");
    EXPECT_GE(std::stoi(query("SELECT count(*) FROM rooms WHERE instance_id = 'b'")), 16);
    // The room closes: its code is free again.
    client.send(proto::Leave{});
    EXPECT_EQ(query_until("SELECT count(*) FROM rooms WHERE code = '" + state->code + "'", "0\n"),
              "0\n");
    // A stale code (its room closed) is no room on any instance.
    for (const auto* server : {a.get(), b.get()}) {
        ManualClient late(server->url(), "late");
        say_hello(late, true);
        late.send(proto::JoinRoom{state->code, proto::Role::Player});
        EXPECT_EQ(late.next_error(), "room_not_found");
    }
}

TEST_F(ClusterRouting, AJoinOnAnotherInstanceIsRedirectedOrNamesTheOwnersUrl) {
    ManualClient owner(a->url(), "owner");
    say_hello(owner, true);
    owner.send(proto::CreateRoom{});
    const std::string code = owner.next<proto::RoomState>().value_or(proto::RoomState{}).code;
    ASSERT_FALSE(code.empty());

    for (const proto::Role role : {proto::Role::Player, proto::Role::Spectator}) {
        ManualClient follower(b->url(), "follower");
        say_hello(follower, true);
        follower.send(proto::JoinRoom{code, role});
        const auto redirect = follower.next<proto::Redirect>();
        ASSERT_TRUE(redirect.has_value());
        EXPECT_EQ(*redirect, (proto::Redirect{a->url(), "room", code, role}));
        EXPECT_NE(follower.wait_closed(3s).find("4005"), std::string::npos);
    }

    ManualClient old(b->url(), "old");
    say_hello(old, false);
    old.send(proto::JoinRoom{code, proto::Role::Player});
    const auto error = old.next<proto::Error>();
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(*error, (proto::Error{"room_elsewhere",
                                    "Room " + code + " is on another server of this cluster: " +
                                        a->url() + " (connect there)."}));
    // The connection stays open: a code no instance has is room_not_found.
    old.send(proto::JoinRoom{"ZZZZZZ", proto::Role::Player});
    EXPECT_EQ(old.next_error(), "room_not_found");
    EXPECT_NE(a->get("/metrics").body.find("carrom_redirects_total 0"), std::string::npos);
    EXPECT_NE(b->get("/metrics").body.find("carrom_redirects_total 2"), std::string::npos);
}

TEST_F(ClusterRouting, AResumeOnAnotherInstanceIsRedirectedToTheSeatsMatch) {
    StartedMatch match = start_match(a->url());
    ASSERT_FALSE(match.code.empty());
    // The seat tokens reach the database with the match's first writes.
    (void)query_until("SELECT count(*) FROM seat_tokens", "2\n");
    ManualClient follower(b->url(), "creator");
    proto::Hello hello{proto::kProtocolVersion, "creator", match.creator_token};
    hello.follows_redirects = true;
    follower.send(hello);
    const auto redirect = follower.next<proto::Redirect>();
    ASSERT_TRUE(redirect.has_value());
    EXPECT_EQ(*redirect, (proto::Redirect{a->url(), "seat", "", proto::Role::Player}));
    EXPECT_NE(follower.wait_closed(3s).find("4005"), std::string::npos);

    ManualClient old(b->url(), "creator");
    old.send(proto::Hello{proto::kProtocolVersion, "creator", match.creator_token});
    const auto error = old.next<proto::Error>();
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(error->code, "seat_elsewhere");
    EXPECT_EQ(error->message, "Your seat's match (room " + match.code +
                                  ") is on another server of this cluster: " + a->url() +
                                  " (resume there).");
    EXPECT_NE(old.wait_closed(3s).find("4004"), std::string::npos);

    // The match API answers the same on every instance.
    const std::string listed = a->get("/matches?player=creator").body;
    EXPECT_NE(listed.find(match.code), std::string::npos) << listed;
    EXPECT_EQ(b->get("/matches?player=creator").body, listed);

    // A token no seat holds is bad_token, as on a server alone.
    ManualClient stranger(b->url(), "stranger");
    stranger.send(proto::Hello{proto::kProtocolVersion, "stranger",
                               std::string("0123456789abcdef0123456789abcdef")});
    EXPECT_EQ(stranger.next_error(), "bad_token");
    EXPECT_TRUE(stranger.next<proto::Welcome>().has_value());
}

TEST_F(ClusterRouting, QuickMatchPairsPlayersWaitingOnTwoInstances) {
    ManualClient first(a->url(), "first");
    say_hello(first, true);
    first.send(proto::QuickMatch{});
    (void)query_until("SELECT count(*) FROM quick_tickets", "1\n");
    ASSERT_EQ(query("SELECT instance_id, rule_set FROM quick_tickets"), "a|icf\n");

    ManualClient second(b->url(), "second");
    say_hello(second, true);
    second.send(proto::QuickMatch{});
    const auto hosted = second.next<proto::RoomState>();
    ASSERT_TRUE(hosted.has_value());
    EXPECT_EQ(hosted->you, 0);
    const auto redirect = first.next<proto::Redirect>(5s);
    ASSERT_TRUE(redirect.has_value());
    EXPECT_EQ(*redirect,
              (proto::Redirect{b->url(), "quick_match", hosted->code, proto::Role::Player}));
    expect_seated_there(*redirect, [](ManualClient& c) { say_hello(c, true); });
    EXPECT_EQ(query("SELECT count(*) FROM quick_tickets"), "0\n");
}

TEST_F(ClusterRouting, RatedQuickMatchPairsIdentifiedPlayersOfTwoInstancesNeverAKeyWithItself) {
    const std::string key1(64, 'a');
    const std::string key2(64, 'b');
    ManualClient first(a->url(), "first");
    say_hello_as(first, "first", key1);
    first.send(proto::QuickMatch{});
    const auto tickets = [&](const std::string& want) {
        (void)query_until("SELECT count(*) FROM quick_tickets", want);
        return query("SELECT instance_id, rule_set, rating, room_code IS NULL FROM quick_tickets "
                     "ORDER BY ticket");
    };
    ASSERT_EQ(tickets("1\n"), "a|icf|1500|t\n");

    // The same key on the other instance waits there; it is never paired with itself.
    {
        ManualClient again(b->url(), "first");
        say_hello_as(again, "first", key1);
        again.send(proto::QuickMatch{});
        ASSERT_EQ(tickets("2\n"), "a|icf|1500|t\nb|icf|1500|t\n");
        std::this_thread::sleep_for(1500ms); // a rated ticket is asked again every second
        EXPECT_EQ(query("SELECT count(*) FROM quick_tickets WHERE room_code IS NULL"), "2\n");
    }
    ASSERT_EQ(tickets("1\n"), "a|icf|1500|t\n"); // withdrawn as its connection ended

    ManualClient second(b->url(), "second");
    say_hello_as(second, "second", key2);
    second.send(proto::QuickMatch{});
    const auto hosted = second.next<proto::RoomState>();
    ASSERT_TRUE(hosted.has_value());
    EXPECT_EQ(hosted->you, 0);
    EXPECT_FALSE(hosted->aim_assist); // a rated room
    const auto redirect = first.next<proto::Redirect>(5s);
    ASSERT_TRUE(redirect.has_value());
    EXPECT_EQ(*redirect,
              (proto::Redirect{b->url(), "quick_match", hosted->code, proto::Role::Player}));
    expect_seated_there(*redirect, [&](ManualClient& c) { say_hello_as(c, "first", key1); });
    EXPECT_EQ(query("SELECT count(*) FROM quick_tickets"), "0\n");
}

TEST_F(ClusterRouting, ARatedHostWhosePartnerNeverComesLeavesForARoomAgainstABot) {
    auto c = start_routed_instance(url, "c", {"--quick-match-bot", "2"});
    ASSERT_NE(c->port(), 0) << c->log();
    ManualClient first(a->url(), "first");
    say_hello_as(first, "first", std::string(64, 'a'));
    first.send(proto::QuickMatch{});
    (void)query_until("SELECT count(*) FROM quick_tickets", "1\n");
    ManualClient host(c->url(), "host");
    say_hello_as(host, "host", std::string(64, 'b'));
    host.send(proto::QuickMatch{});
    const auto rated = host.next<proto::RoomState>();
    ASSERT_TRUE(rated.has_value());
    EXPECT_FALSE(rated->aim_assist);
    ASSERT_TRUE(first.next<proto::Redirect>(5s).has_value()); // and it never goes there
    // The wait (2 s on c) is over: a room against a bot, unrated, this player in seat 0.
    const auto against_bot = host.next<proto::RoomState>(5s);
    ASSERT_TRUE(against_bot.has_value()) << c->log();
    EXPECT_NE(against_bot->code, rated->code);
    EXPECT_TRUE(against_bot->aim_assist);
    EXPECT_EQ(against_bot->you, 0);
    EXPECT_TRUE(host.next_event<proto::TurnEvent>().has_value()); // the bot is seated: play
    // The rated room closed with nobody in it: its code is free again.
    EXPECT_EQ(query_until("SELECT count(*) FROM rooms WHERE code = '" + rated->code + "'", "0\n"),
              "0\n");
}

TEST_F(ClusterRouting, RatedPlayersOfTwoInstancesTooFarApartWaitAndGuestsDoNotTakeTheirTickets) {
    const std::string strong(64, 'c');
    {
        // A known player rated 2300 in icf.
        ManualClient once(a->url(), "strong");
        say_hello_as(once, "strong", strong);
        (void)query_until("SELECT count(*) FROM identities", "1\n");
        query("INSERT INTO ratings SELECT key_sha256, 'icf', 2300, 60, 0.06, 30, 20, 10, 0, 0 "
              "FROM identities");
    }
    ManualClient first(a->url(), "strong");
    say_hello_as(first, "strong", strong);
    first.send(proto::QuickMatch{});
    (void)query_until("SELECT count(*) FROM quick_tickets", "1\n");
    ASSERT_EQ(query("SELECT instance_id, rating FROM quick_tickets"), "a|2300\n");

    // 800 points apart: not within the gap (100 points and 25 more per second waited).
    ManualClient newcomer(b->url(), "newcomer");
    say_hello_as(newcomer, "newcomer", std::string(64, 'd'));
    newcomer.send(proto::QuickMatch{});
    // A guest waits for guests: a rated ticket is not its partner either.
    ManualClient guest(b->url(), "guest");
    say_hello(guest, true, std::nullopt, "guest");
    guest.send(proto::QuickMatch{});
    std::this_thread::sleep_for(2s);
    EXPECT_EQ(
        query("SELECT instance_id, rating FROM quick_tickets ORDER BY rating DESC NULLS LAST"),
        "a|2300\nb|1500\nb|\n");
    EXPECT_FALSE(first.next<proto::Redirect>(100ms).has_value());
    EXPECT_FALSE(newcomer.next<proto::RoomState>(100ms).has_value());
}

TEST_F(ClusterRouting, SigtermHandsTheMatchToTheOtherInstanceAndSendsItsPlayersThere) {
    StartedMatch match = start_match(a->url());
    ASSERT_FALSE(match.code.empty());
    ManualClient spectator(a->url(), "watcher");
    say_hello(spectator, true);
    spectator.send(proto::JoinRoom{match.code, proto::Role::Spectator});
    ASSERT_TRUE(spectator.next<proto::RoomState>().has_value());

    a->terminate();
    const auto redirect = match.creator->next<proto::Redirect>(5s);
    ASSERT_TRUE(redirect.has_value()) << a->log();
    EXPECT_EQ(*redirect, (proto::Redirect{b->url(), "moved", match.code, proto::Role::Player}));
    const auto watched = spectator.next<proto::Redirect>(5s);
    ASSERT_TRUE(watched.has_value());
    EXPECT_EQ(watched->as, proto::Role::Spectator);
    EXPECT_EQ(query("SELECT owner_instance FROM matches"), "b\n");
    EXPECT_EQ(query("SELECT instance_id FROM rooms WHERE code = '" + match.code + "'"), "b\n");

    // The seat resumes on b (at once, or after match_moving while b restores it).
    std::optional<proto::RoomState> state;
    for (int attempt = 0; attempt < 20 && !state; ++attempt) {
        ManualClient resumed(b->url(), "creator");
        const proto::Welcome welcome = say_hello(resumed, true, match.creator_token);
        if (welcome.resume_token == match.creator_token) {
            state = resumed.next<proto::RoomState>();
        } else {
            std::this_thread::sleep_for(200ms);
        }
    }
    ASSERT_TRUE(state.has_value()) << b->log();
    EXPECT_EQ(state->code, match.code);
    EXPECT_EQ(state->you, 0);
    EXPECT_TRUE(b->wait_log("handed over to this instance", std::chrono::steady_clock::now() + 1s));
    // How long the hand-over took (docs/cluster.md, "Draining"): from a's SIGTERM to the match
    // restored on b, by the two logs' clocks (one machine).
    const auto signalled = a->wait_log("signal 15", std::chrono::steady_clock::now());
    const auto restored =
        b->wait_log("room " + match.code + " taken over", std::chrono::steady_clock::now());
    ASSERT_TRUE(signalled && restored);
    const double ms = log_time_ms(*restored) - log_time_ms(*signalled);
    EXPECT_GT(ms, 0.0);
    std::printf("match running on b %.0f ms after SIGTERM to a\n", ms);
}

TEST_F(ClusterRouting, SigtermHandsARoomWaitingForItsPlayersToTheOtherInstanceWithItsCode) {
    ManualClient creator(a->url(), "creator");
    say_hello(creator, true, std::nullopt, "creator");
    proto::CreateRoom create;
    create.options.boards = 3;
    creator.send(create);
    const auto waiting = creator.next<proto::RoomState>();
    ASSERT_TRUE(waiting.has_value());
    ASSERT_EQ(waiting->phase, proto::Phase::Waiting);
    ManualClient watcher(a->url(), "watcher");
    say_hello(watcher, true);
    watcher.send(proto::JoinRoom{waiting->code, proto::Role::Spectator});
    ASSERT_TRUE(watcher.next<proto::RoomState>().has_value());

    a->terminate();
    const auto moved = creator.next<proto::Redirect>(5s);
    ASSERT_TRUE(moved.has_value()) << a->log();
    EXPECT_EQ(*moved, (proto::Redirect{b->url(), "moved", waiting->code, proto::Role::Player}));
    const auto watched = watcher.next<proto::Redirect>(5s);
    ASSERT_TRUE(watched.has_value());
    EXPECT_EQ(watched->as, proto::Role::Spectator);
    EXPECT_TRUE(
        a->wait_log("and 1 rooms waiting for their players", std::chrono::steady_clock::now() + 5s))
        << a->log();

    // On b the room is there under its code, with its options, empty until its members come.
    ASSERT_TRUE(b->wait_log("room " + waiting->code + " handed over: waiting for its players",
                            std::chrono::steady_clock::now() + 5s))
        << b->log();
    EXPECT_EQ(query("SELECT instance_id, waiting IS NULL FROM rooms WHERE code = '" +
                    waiting->code + "'"),
              "b|t\n");
    ManualClient back(moved->url, "creator");
    say_hello(back, true, std::nullopt, "creator");
    back.send(proto::JoinRoom{moved->code, moved->as});
    const auto seated = back.next<proto::RoomState>();
    ASSERT_TRUE(seated.has_value());
    EXPECT_EQ(seated->you, 0);
    EXPECT_EQ(seated->phase, proto::Phase::Waiting);
    // The friend with the code finds it through either instance's address: b's here.
    ManualClient friend_(b->url(), "friend");
    say_hello(friend_, true, std::nullopt, "friend");
    friend_.send(proto::JoinRoom{waiting->code, proto::Role::Player});
    const auto joined = friend_.next<proto::RoomState>();
    ASSERT_TRUE(joined.has_value());
    EXPECT_EQ(joined->you, 1);
    EXPECT_TRUE(back.next_event<proto::TurnEvent>().has_value());
    EXPECT_EQ(
        query("SELECT (head::jsonb)->'rules'->>'max_boards' FROM matches WHERE room_code = '" +
              waiting->code + "'"),
        "3\n");
}

TEST_F(ClusterRouting, AHandedOverWaitingRoomNobodyComesBackToClosesAfterTheGracePeriod) {
    auto c = start_routed_instance(url, "c", {"--grace", "1"});
    ASSERT_NE(c->port(), 0) << c->log();
    b->terminate(); // (nothing to hand over) c is the only instance a can hand its room to
    ManualClient creator(a->url(), "creator");
    say_hello(creator, true, std::nullopt, "creator");
    creator.send(proto::CreateRoom{});
    const auto waiting = creator.next<proto::RoomState>();
    ASSERT_TRUE(waiting.has_value());
    a->terminate();
    const auto moved = creator.next<proto::Redirect>(5s);
    ASSERT_TRUE(moved.has_value()) << a->log();
    EXPECT_EQ(moved->url, c->url());
    ASSERT_TRUE(c->wait_log("room " + waiting->code + ": nobody came back to it",
                            std::chrono::steady_clock::now() + 5s))
        << c->log();
    EXPECT_EQ(query_until("SELECT count(*) FROM rooms WHERE code = '" + waiting->code + "'", "0\n"),
              "0\n");
    ManualClient late(c->url(), "late");
    say_hello(late, true);
    late.send(proto::JoinRoom{waiting->code, proto::Role::Player});
    EXPECT_EQ(late.next_error(), "room_not_found");
}

TEST_F(ClusterRouting, AHandedOverRoomWithABadDescriptionIsLoggedAndFreedAndHarmsNothing) {
    query("INSERT INTO rooms (code, instance_id, waiting) VALUES ('QQQQQQ', 'b', "
          "'{\"rule_set\": \"chess\", \"rules\": {}, \"rated\": false}'); "
          "NOTIFY carrom_cluster_wake");
    const auto logged = b->wait_log("room QQQQQQ handed over but not opened",
                                    std::chrono::steady_clock::now() + 5s);
    ASSERT_TRUE(logged) << b->log();
    EXPECT_NE(logged->find("(bad_waiting_room: A handed-over room's description has no known "
                           "rule_set.)"),
              std::string::npos)
        << *logged;
    EXPECT_EQ(query_until("SELECT count(*) FROM rooms WHERE code = 'QQQQQQ'", "0\n"), "0\n");
    // b goes on: its lease renewed, its rooms open.
    EXPECT_EQ(b->log().find("cannot renew its lease"), std::string::npos) << b->log();
    ManualClient client(b->url());
    say_hello(client, true);
    client.send(proto::CreateRoom{});
    EXPECT_TRUE(client.next<proto::RoomState>().has_value());
}

} // namespace
} // namespace carrom::integration
