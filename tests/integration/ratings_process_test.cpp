// Identities and ratings end to end (docs/ratings.md): carrom-server --data as a real process;
// carrom-bot processes with --identity play a rated match and both ratings change, and survive a
// restart unchanged (on SQLite and on PostgreSQL); names held by identities; rated rooms' refusals;
// quick match pairing by rating; the players' API and its bad inputs.
#include "harness.hpp"

#include "support/postgres_instance.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include "store/sha256.hpp"

#include <SQLiteCpp/SQLiteCpp.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <thread>

#include <sys/stat.h>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;
using RatingsJson = nlohmann::json;

class RatingsDir : public test_support::TempDir {
public:
    RatingsDir() : test_support::TempDir("carrom_ratings") {}
};

std::unique_ptr<test_support::ServerProcess>
start_rated_server(const std::string& data, std::vector<std::string> more = {}) {
    test_support::ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.data = data;
    options.args = {"--time-scale", "25", "--log-level", "info", "--max-connections-per-address",
                    "1000"};
    options.args.insert(options.args.end(), more.begin(), more.end());
    if (data.starts_with("postgresql://")) { // cluster mode: one instance, the same after a restart
        options.args.insert(options.args.end(),
                            {"--instance-id", "ratings", "--public-url", "ws://127.0.0.1:7777"});
    }
    return std::make_unique<test_support::ServerProcess>(options);
}

std::string key_of(char digit) {
    return std::string(64, digit);
}

proto::Hello hello_as(const std::string& name, std::optional<std::string> identity) {
    proto::Hello hello{proto::kProtocolVersion, name, std::nullopt};
    hello.identity = std::move(identity);
    return hello;
}

// A client that said hello with a key; fails the test unless welcomed.
std::unique_ptr<ManualClient> identified(const std::string& url, const std::string& name,
                                         const std::string& key) {
    auto client = std::make_unique<ManualClient>(url, name);
    client->send(hello_as(name, key));
    EXPECT_TRUE(client->next<proto::Welcome>().has_value()) << name;
    return client;
}

// The code of the first error that comes to a hello (or "" when welcomed).
std::string hello_refusal(const std::string& url, const std::string& name,
                          std::optional<std::string> identity) {
    ManualClient client(url, name);
    client.send(hello_as(name, std::move(identity)));
    for (int i = 0; i < 50; ++i) {
        client.drain(20ms);
        for (const auto& m : client.history()) {
            if (const auto* e = std::get_if<proto::Error>(&m)) {
                return e->code;
            }
            if (std::holds_alternative<proto::Welcome>(m)) {
                return "";
            }
        }
    }
    return "timeout";
}

RatingsJson get_json(const test_support::ServerProcess& server, const std::string& target,
                     int expect_status = 200) {
    const auto answer = server.get(target);
    EXPECT_EQ(answer.status, expect_status) << target << ": " << answer.body;
    return RatingsJson::parse(answer.body, nullptr, false);
}

// Two carrom-bot processes with keys play a rated match through a server on data; both ratings
// move, and a restart on the same data keeps them and applies nothing again.
void play_a_rated_match_then_restart(const std::string& data, const RatingsDir& dir) {
    auto server = start_rated_server(data);
    ASSERT_NE(server->port(), 0) << server->log();
    const std::string bot = CARROM_BOT_PATH;
    const std::string common = " --url " + server->url() +
                               " --strategy sampling --think-ms 50 --timeout 90 2>> " +
                               dir.file("bots.err");
    CommandRun creator;
    std::thread creator_thread([&] {
        creator = run_command(bot + " --identity " + dir.file("asha.key") +
                              " --name Asha --create --rated --rule-set freestyle" +
                              " --target-points 20 --shot-clock 0 --seed 3" + common);
    });
    std::string code;
    for (int i = 0; i < 200 && code.size() != 6; ++i) {
        std::this_thread::sleep_for(25ms);
        std::ifstream err(dir.file("bots.err"));
        std::string word;
        while (err >> word) {
            if (word == "room" && err >> code) {
                break;
            }
        }
    }
    ASSERT_EQ(code.size(), 6U) << server->log();
    const CommandRun joiner = run_command(bot + " --identity " + dir.file("ravi.key") +
                                          " --name Ravi --join " + code + " --seed 4" + common);
    creator_thread.join();
    ASSERT_EQ(creator.exit, 0) << creator.out;
    ASSERT_EQ(joiner.exit, 0) << joiner.out;

    // Each key file: one key and a newline, readable by its owner only.
    struct stat st {};
    ASSERT_EQ(::stat(dir.file("asha.key").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0600U);
    EXPECT_EQ(st.st_size, 65);

    const RatingsJson asha = get_json(*server, "/players/Asha");
    const RatingsJson ravi = get_json(*server, "/players/ravi"); // names compare case-folded
    EXPECT_EQ(ravi["name"], "Ravi");
    ASSERT_EQ(asha["ratings"].size(), 1U) << asha.dump();
    ASSERT_EQ(ravi["ratings"].size(), 1U) << ravi.dump();
    const RatingsJson a = asha["ratings"][0];
    const RatingsJson r = ravi["ratings"][0];
    EXPECT_EQ(a["rule_set"], "freestyle");
    EXPECT_EQ(a["games"], 1);
    EXPECT_EQ(r["games"], 1);
    EXPECT_EQ(a["wins"].get<int>() + r["wins"].get<int>() + a["draws"].get<int>(), 1);
    EXPECT_EQ(a["provisional"], true);
    // Two new players: the winner gains what the loser gives (about 162 points each way).
    EXPECT_NEAR(a["rating"].get<double>() + r["rating"].get<double>(), 3000.0, 1e-6);
    if (a["wins"] == 1) {
        EXPECT_NEAR(a["rating"].get<double>(), 1662.3, 0.1);
    }
    ASSERT_EQ(asha["matches"].size(), 1U);
    EXPECT_EQ(asha["matches"][0]["replay"],
              "/matches/" + asha["matches"][0]["id"].get<std::string>());
    EXPECT_EQ(server->get(asha["matches"][0]["replay"].get<std::string>()).status, 200);
    // Provisional ratings stay off the leaderboard.
    EXPECT_TRUE(get_json(*server, "/leaderboard?rule_set=freestyle")["players"].empty());

    // A restart keeps every rating as it was and applies nothing again.
    server->terminate();
    ASSERT_TRUE(server->restart()) << server->log();
    EXPECT_EQ(get_json(*server, "/players/Asha")["ratings"], asha["ratings"]);
    EXPECT_EQ(get_json(*server, "/players/Ravi")["ratings"], ravi["ratings"]);
    // The name stays Asha's after the restart: another key, or a guest, cannot take it.
    EXPECT_EQ(hello_refusal(server->url(), "ASHA", key_of('5')), "name_taken");
    EXPECT_EQ(hello_refusal(server->url(), "asha", std::nullopt), "name_taken");
}

TEST(RatingsProcess, TwoBotProcessesWithIdentitiesPlayARatedMatchAndBothRatingsMove) {
    RatingsDir dir;
    play_a_rated_match_then_restart(dir.file("c.db"), dir);
}

// The same on PostgreSQL (--data postgresql://...): the ratings tables, the update with the
// result, and a restart on the same database.
TEST(RatingsProcess, OnPostgresqlARatedMatchMovesBothRatingsAndARestartKeepsThem) {
    RatingsDir dir;
    test_support::PostgresInstance postgres;
    play_a_rated_match_then_restart(postgres.url(postgres.create_database()), dir);
}

TEST(RatingsProcess, NamesKeysAndRatedRoomsAreRefusedWithTheirCodes) {
    RatingsDir dir;
    auto server = start_rated_server(dir.file("c.db"));
    const std::string url = server->url();
    auto asha = identified(url, "Asha", key_of('a'));
    // One name per identity at once; compared by NFKC case fold, spaces collapsed.
    EXPECT_EQ(hello_refusal(url, "asha", key_of('b')), "name_taken");
    EXPECT_EQ(hello_refusal(url, "\xef\xbc\xa1sha", key_of('b')), "name_taken"); // fullwidth A
    EXPECT_EQ(hello_refusal(url, "Asha", std::nullopt), "name_taken");           // a guest
    EXPECT_EQ(hello_refusal(url, "Bea", key_of('b')), "");
    EXPECT_EQ(hello_refusal(url, "Asha", key_of('a')), ""); // the holder, on a second connection
    // Malformed keys, over-long names and control characters.
    EXPECT_EQ(hello_refusal(url, "Cy", std::string(64, 'A')), "bad_identity");
    EXPECT_EQ(hello_refusal(url, "Cy", "not a key"), "bad_identity");
    EXPECT_EQ(hello_refusal(url, std::string(25, 'c'), key_of('c')), "bad_field");
    EXPECT_EQ(hello_refusal(url, "C\ty", key_of('c')), "bad_field");

    // Rated rooms: no bot, no doubles, no guest; one key cannot hold both seats.
    proto::CreateRoom rated;
    rated.rated = true;
    proto::CreateRoom with_bot = rated;
    with_bot.bot = proto::BotSeat{};
    asha->send(with_bot);
    EXPECT_EQ(asha->next_error(), "rated_with_bot");
    proto::CreateRoom doubles = rated;
    doubles.seats = 4;
    asha->send(doubles);
    EXPECT_EQ(asha->next_error(), "rated_doubles");
    ManualClient guest(url, "Guest");
    guest.hello();
    guest.send(rated);
    EXPECT_EQ(guest.next_error(), "identity_required");
    asha->send(rated);
    const auto state = asha->next<proto::RoomState>();
    ASSERT_TRUE(state.has_value());
    EXPECT_FALSE(state->aim_assist) << "a rated room has no aim assist";
    auto asha_again = identified(url, "Asha", key_of('a'));
    asha_again->send(proto::JoinRoom{state->code, proto::Role::Player});
    EXPECT_EQ(asha_again->next_error(), "same_player");
    guest.send(proto::JoinRoom{state->code, proto::Role::Player});
    EXPECT_EQ(guest.next_error(), "identity_required");
}

TEST(RatingsProcess, NewIdentitiesFromOneAddressAreLimitedPerMinute) {
    RatingsDir dir;
    auto server = start_rated_server(dir.file("c.db"));
    for (char digit : std::string("01234")) {
        EXPECT_EQ(hello_refusal(server->url(), std::string("P") + digit, key_of(digit)), "");
    }
    EXPECT_EQ(hello_refusal(server->url(), "P5", key_of('5')), "too_many_identities");
    EXPECT_EQ(hello_refusal(server->url(), "P0", key_of('0')), ""); // a known key is no new one
}

// Ratings written into the store before the server starts: 1000, 1300, 1600 and 1750.
void seed_ratings(const std::string& path, const std::array<double, 4>& ratings) {
    SQLite::Database db(path, SQLite::OPEN_READWRITE);
    for (int i = 0; i < 4; ++i) {
        const std::string key = key_of(static_cast<char>('1' + i));
        const store::Sha256Digest hash = store::sha256(key);
        const std::string name = "R" + std::to_string(i + 1);
        SQLite::Statement player(db, "INSERT INTO identities VALUES (?, ?, ?, 0)");
        player.bind(1, hash.data(), 32);
        player.bind(2, name);
        player.bind(3, "r" + std::to_string(i + 1));
        player.exec();
        SQLite::Statement rating(db, "INSERT INTO ratings VALUES (?, 'icf', ?, 80, 0.06, 20, 10, "
                                     "10, 0, 0)");
        rating.bind(1, hash.data(), 32);
        rating.bind(2, ratings[static_cast<std::size_t>(i)]);
        rating.exec();
    }
}

TEST(RatingsProcess, QuickMatchPairsTheClosestRatingsAsTheGapWidens) {
    RatingsDir dir;
    auto server = start_rated_server(dir.file("c.db"), {"--quick-match-bot", "0"});
    server->terminate(); // the schema is there; the ratings go in before the next start
    seed_ratings(dir.file("c.db"), {1000.0, 1300.0, 1600.0, 1750.0});
    ASSERT_TRUE(server->restart()) << server->log();
    std::vector<std::unique_ptr<ManualClient>> players;
    for (int i = 0; i < 4; ++i) {
        players.push_back(identified(server->url(), "R" + std::to_string(i + 1),
                                     key_of(static_cast<char>('1' + i))));
    }
    for (auto& p : players) {
        p->send(proto::QuickMatch{});
    }
    // 1600 and 1750 meet once the gap reaches 150 (2 s); 1000 and 1300 at 300 (8 s).
    std::array<std::string, 4> rooms;
    for (std::size_t i = 0; i < 4; ++i) {
        const auto state = players[i]->next<proto::RoomState>(15s);
        ASSERT_TRUE(state.has_value()) << i << "\n" << server->log();
        rooms[i] = state->code;
    }
    EXPECT_EQ(rooms[2], rooms[3]);
    EXPECT_EQ(rooms[0], rooms[1]);
    EXPECT_NE(rooms[0], rooms[2]);
}

TEST(RatingsProcess, APlayerIsKnownToThePlayersApiAsSoonAsItsHelloIsAnswered) {
    RatingsDir dir;
    auto server = start_rated_server(dir.file("c.db"));
    for (const char digit : {'1', '2', '3', '4', '5'}) { // the address's burst of new keys
        const std::string name = std::string("Player") + digit;
        auto client = identified(server->url(), name, key_of(digit));
        const RatingsJson player = get_json(*server, "/players/" + name);
        EXPECT_EQ(player["name"], name);
        EXPECT_TRUE(player["ratings"].empty());
        EXPECT_TRUE(player["matches"].empty());
    }
}

TEST(RatingsProcess, ThePlayersApiAnswersBadInputsWithCodes) {
    RatingsDir dir;
    auto server = start_rated_server(dir.file("c.db"));
    const auto code = [&](const std::string& target, int status) {
        return get_json(*server, target, status)["error"]["code"].get<std::string>();
    };
    EXPECT_EQ(code("/players/Nobody", 404), "unknown_player");
    EXPECT_EQ(code("/players/%ZZ", 400), "bad_player_name");
    EXPECT_EQ(code("/players/", 400), "bad_player_name");
    EXPECT_EQ(code("/players/" + std::string(25, 'x'), 400), "bad_player_name");
    EXPECT_EQ(code("/players/a%09b", 400), "bad_player_name");
    EXPECT_EQ(code("/players/Asha?x=1", 400), "bad_query");
    EXPECT_EQ(code("/leaderboard?rule_set=chess", 400), "bad_query");
    EXPECT_EQ(code("/leaderboard?limit=0", 400), "bad_query");
    EXPECT_EQ(code("/leaderboard?limit=101", 400), "bad_query");
    EXPECT_EQ(code("/leaderboard?limit=5x", 400), "bad_query");
    EXPECT_EQ(code("/leaderboard?sort=name", 400), "bad_query");
    const RatingsJson board = get_json(*server, "/leaderboard?rule_set=discpool&limit=100");
    EXPECT_EQ(board["rule_set"], "discpool");
    EXPECT_TRUE(board["players"].empty());
    EXPECT_EQ(get_json(*server, "/players")["kept"], true);
    auto none = start_rated_server("none");
    EXPECT_EQ(get_json(*none, "/leaderboard", 503)["error"]["code"], "store_disabled");
    EXPECT_EQ(get_json(*none, "/players/Asha", 503)["error"]["code"], "store_disabled");
    EXPECT_EQ(get_json(*none, "/players")["kept"], false);
}

} // namespace
} // namespace carrom::integration
