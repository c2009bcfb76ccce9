// Doubles (four seats, partners opposite) end to end against carrom-server as a program: four
// carrom-bot processes play a whole match; two players over the net library with two server
// bots, watched by a spectator to the end; a side seat whose connection is cut resumes; quick
// matches for doubles, of four players or of one player and server bots.
#include "harness.hpp"
#include "support/child_process.hpp"
#include "support/server_process.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <set>
#include <thread>

namespace carrom::integration {
namespace {

using test_support::ChildProcess;
using test_support::ServerProcess;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

// carrom-server on 127.0.0.1 (an ephemeral port), no store, fast playback, no shot clock, server
// bots thinking 40 ms a stroke.
ServerProcess::Options server_options(const std::vector<std::string>& extra = {}) {
    ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.args = {"--time-scale",   "25", "--shot-clock", "0",
                    "--bot-think-ms", "40", "--log-level",  "warn"};
    options.args.insert(options.args.end(), extra.begin(), extra.end());
    return options;
}

// A short doubles game: one icf board (the first team to clear its coins wins the game).
proto::CreateRoom one_board_doubles() {
    proto::CreateRoom create;
    create.rule_set = proto::RuleSet::Icf;
    create.seats = 4;
    create.options.boards = 1;
    create.options.target_points = 1;
    create.options.shot_clock_s = 0.0;
    return create;
}

// Steps the runners until every one is done or the timeout passes.
void run_all(const std::vector<bots::BotRunner*>& runners, std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    for (;;) {
        bool all_done = true;
        for (auto* runner : runners) {
            all_done = all_done && runner->done();
        }
        if (all_done || Clock::now() >= deadline) {
            return;
        }
        for (auto* runner : runners) {
            runner->step(2ms);
        }
    }
}

// Steps `runner` (and the others) until it has a room; its code.
std::string wait_for_room(bots::BotRunner& runner, std::chrono::milliseconds timeout = 15s) {
    const auto deadline = Clock::now() + timeout;
    while (!runner.room() && !runner.done() && Clock::now() < deadline) {
        runner.step(20ms);
    }
    return runner.room() ? runner.room()->code : std::string();
}

bots::BotConfig config_for(const std::string& url, bots::JoinMode mode, const std::string& name) {
    bots::BotConfig config;
    config.url = url;
    config.mode = mode;
    config.name = name;
    config.budget.time = 40ms;
    return config;
}

// Partners end with the same result, opponents with opposite ones; every seat shot.
void expect_team_results(const std::map<int, nlohmann::json>& by_seat) {
    ASSERT_EQ(by_seat.size(), 4u);
    const auto scores = by_seat.at(0)["scores"];
    ASSERT_EQ(scores.size(), 4u) << scores.dump();
    EXPECT_EQ(scores[0], scores[2]);
    EXPECT_EQ(scores[1], scores[3]);
    for (const auto& [seat, s] : by_seat) {
        EXPECT_EQ(s["team"], seat % 2) << s.dump();
        EXPECT_EQ(s["scores"], scores) << s.dump();
        EXPECT_EQ(s["result"], by_seat.at(seat % 2)["result"]) << s.dump();
        EXPECT_GT(s["shots"].get<int>(), 0) << "seat " << seat << " never shot: " << s.dump();
    }
    EXPECT_NE(by_seat.at(0)["result"], by_seat.at(1)["result"]);
    const std::set<std::string> results{by_seat.at(0)["result"].get<std::string>(),
                                        by_seat.at(1)["result"].get<std::string>()};
    EXPECT_EQ(results, (std::set<std::string>{"won", "lost"}));
}

TEST(Doubles, FourBotProcessesPlayAWholeMatch) {
    ServerProcess server(server_options());
    ASSERT_NE(server.port(), 0) << server.log();
    const std::vector<std::string> common{"--url",     server.url(), "--strategy",   "greedy",
                                          "--level",   "easy",       "--think-ms",   "40",
                                          "--timeout", "150",        "--resume-for", "0"};
    std::vector<std::unique_ptr<ChildProcess>> bots;
    std::vector<std::string> creator{
        CARROM_BOT_PATH,   "--create", "--seats",      "4", "--rule-set", "icf", "--boards", "1",
        "--target-points", "1",        "--shot-clock", "0", "--seed",     "1"};
    creator.insert(creator.end(), common.begin(), common.end());
    bots.push_back(std::make_unique<ChildProcess>(creator));
    const auto line = bots[0]->wait_line(ChildProcess::Stream::Err, "room ", Clock::now() + 15s);
    ASSERT_TRUE(line.has_value()) << bots[0]->output();
    const std::string code = line->substr(5);
    for (int i = 1; i < 4; ++i) {
        std::vector<std::string> joiner{CARROM_BOT_PATH, "--join", code, "--seed",
                                        std::to_string(i + 1)};
        joiner.insert(joiner.end(), common.begin(), common.end());
        bots.push_back(std::make_unique<ChildProcess>(joiner));
    }
    std::map<int, nlohmann::json> by_seat;
    for (auto& bot : bots) {
        const auto out = bot->wait_line(ChildProcess::Stream::Out, "{", Clock::now() + 180s);
        ASSERT_TRUE(out.has_value()) << bot->output();
        const auto s = nlohmann::json::parse(*out);
        EXPECT_EQ(s["ok"], true) << s.dump() << "\n" << bot->output();
        EXPECT_EQ(s["room"], code);
        EXPECT_EQ(s["games"], 1);
        EXPECT_EQ(s["errors"], nlohmann::json::object()) << s.dump();
        EXPECT_EQ(s["decode_errors"], 0);
        EXPECT_EQ(s["unrepaired_gaps"], 0);
        by_seat[s["seat"].get<int>()] = s;
        EXPECT_EQ(bot->wait_exit(Clock::now() + 10s), 0);
    }
    expect_team_results(by_seat);
}

TEST(Doubles, TwoPlayersWithTwoServerBotsWatchedByASpectatorToTheEnd) {
    ServerProcess server(server_options());
    ASSERT_NE(server.port(), 0) << server.log();
    // Seats 0 and 1 are players over the net library, each with a server bot as partner
    // (seats 2 and 3).
    // Random players: a stronger one can clear the board in its first turn, before every seat
    // has shot.
    auto s0 = test_strategy("random", 1);
    auto s1 = test_strategy("random", 2);
    auto watcher = test_strategy("random", 3);
    auto config = config_for(server.url(), bots::JoinMode::Create, "north");
    config.create = one_board_doubles();
    proto::BotSeat bot_seats;
    bot_seats.level = proto::BotLevel::Easy;
    bot_seats.seats = {2, 3};
    config.create.bot = bot_seats;
    bots::BotRunner first(config, *s0);
    first.start();
    const std::string code = wait_for_room(first);
    ASSERT_FALSE(code.empty()) << first.summary().failure;

    auto watch = config_for(server.url(), bots::JoinMode::Spectate, "watcher");
    watch.code = code;
    bots::BotRunner spectator(watch, *watcher);
    std::set<int> shooters;                 // seats of every shot_result the spectator saw
    std::optional<proto::RoomState> last;   // the last room_state it saw
    std::optional<proto::GameEndEvent> end; // the game_end it saw
    spectator.on_message = [&](const proto::ServerMessage& m) {
        if (const auto* r = std::get_if<proto::ShotResult>(&m)) {
            shooters.insert(r->seat);
        } else if (const auto* room = std::get_if<proto::RoomState>(&m)) {
            last = *room;
        } else if (const auto* e = std::get_if<proto::Event>(&m)) {
            if (const auto* g = std::get_if<proto::GameEndEvent>(e)) {
                end = *g;
            }
        }
    };
    spectator.start();
    ASSERT_EQ(wait_for_room(spectator), code) << spectator.summary().failure;

    auto join = config_for(server.url(), bots::JoinMode::Join, "east");
    join.code = code;
    bots::BotRunner second(join, *s1);
    second.start();
    run_all({&first, &second, &spectator}, 150s);

    for (const auto* runner : {&first, &second, &spectator}) {
        EXPECT_TRUE(runner->summary().finished) << runner->summary().failure;
        EXPECT_TRUE(runner->summary().errors.empty()) << runner->summary().errors.begin()->first;
        EXPECT_EQ(runner->summary().games, 1);
        EXPECT_EQ(runner->summary().scores, first.summary().scores);
    }
    EXPECT_EQ(first.summary().seat, 0);
    EXPECT_EQ(second.summary().seat, 1);
    EXPECT_EQ(spectator.summary().seat, -1);
    EXPECT_EQ(first.summary().wins, second.summary().losses);
    EXPECT_EQ(first.summary().losses, second.summary().wins);
    EXPECT_GT(first.summary().shots, 0);
    EXPECT_GT(second.summary().shots, 0)
        << "game_end: " << (end ? end->reason : std::string("none"))
        << ", shots by seat 0: " << first.summary().shots;
    // The spectator saw every seat shoot, the bots in their seats, and the game to its end.
    EXPECT_EQ(shooters, (std::set<int>{0, 1, 2, 3}));
    ASSERT_TRUE(last.has_value());
    ASSERT_EQ(last->seats.size(), 4u);
    EXPECT_FALSE(last->seats[0].bot);
    EXPECT_FALSE(last->seats[1].bot);
    EXPECT_TRUE(last->seats[2].bot);
    EXPECT_TRUE(last->seats[3].bot);
    const proto::Baseline sides[] = {proto::Baseline::Bottom, proto::Baseline::Right,
                                     proto::Baseline::Top, proto::Baseline::Left};
    for (std::size_t s = 0; s < 4; ++s) {
        EXPECT_EQ(last->seats[s].team, static_cast<int>(s % 2));
        EXPECT_EQ(last->seats[s].baseline, sides[s]);
    }
    ASSERT_TRUE(end.has_value());
    EXPECT_TRUE(end->winner == 0 || end->winner == 1) << end->winner;
    EXPECT_EQ(first.summary().wins, end->winner == 0 ? 1 : 0);
    ASSERT_EQ(end->scores.size(), 4u);
    EXPECT_EQ(end->scores[0], end->scores[2]);
    EXPECT_EQ(end->scores[1], end->scores[3]);
}

TEST(Doubles, ASideSeatCutOffMidMatchResumesAndPlaysOn) {
    ServerProcess server(server_options({"--grace", "30"}));
    ASSERT_NE(server.port(), 0) << server.log();
    // Seat 2 is a server bot; players take seats 0, 1 and 3 (the left side) in that order.
    auto s0 = test_strategy("random", 1);
    auto s1 = test_strategy("random", 2);
    auto s3 = test_strategy("random", 3);
    auto config = config_for(server.url(), bots::JoinMode::Create, "south");
    config.create = one_board_doubles();
    config.create.rule_set = proto::RuleSet::Freestyle;
    config.create.options.target_points = 80;
    proto::BotSeat bot_seat;
    bot_seat.level = proto::BotLevel::Random;
    bot_seat.seats = {2};
    config.create.bot = bot_seat;
    bots::BotRunner south(config, *s0);
    std::vector<int> dropped_seats; // player_dropped events south heard
    south.on_message = [&](const proto::ServerMessage& m) {
        if (const auto* e = std::get_if<proto::Event>(&m)) {
            if (const auto* d = std::get_if<proto::PlayerDroppedEvent>(e)) {
                dropped_seats.push_back(d->seat);
            }
        }
    };
    south.start();
    const std::string code = wait_for_room(south);
    ASSERT_FALSE(code.empty()) << south.summary().failure;
    auto join = config_for(server.url(), bots::JoinMode::Join, "east");
    join.code = code;
    bots::BotRunner east(join, *s1);
    east.start();
    ASSERT_EQ(wait_for_room(east), code);
    join.name = "west";
    bots::BotRunner west(join, *s3);
    int west_shots_sent = 0;
    west.on_shoot = [&](const proto::Shoot&) { ++west_shots_sent; };
    west.start();
    ASSERT_EQ(wait_for_room(west), code);
    ASSERT_EQ(west.room()->you, 3);

    // Play until west (left side) sent its first shot, then cut it off.
    const auto deadline = Clock::now() + 60s;
    while (west_shots_sent == 0 && !west.done() && Clock::now() < deadline) {
        for (auto* runner : {&south, &east, &west}) {
            runner->step(2ms);
        }
    }
    ASSERT_EQ(west_shots_sent, 1) << west.summary().failure;
    const std::string token = west.resume_token();
    west.drop();
    const auto heard_deadline = Clock::now() + 15s;
    while (dropped_seats.empty() && Clock::now() < heard_deadline) {
        south.step(5ms);
        east.step(5ms);
    }
    ASSERT_EQ(dropped_seats, (std::vector<int>{3}));
    west.resume();
    run_all({&south, &east, &west}, 150s);

    EXPECT_EQ(west.resume_token(), token);
    EXPECT_EQ(west.summary().resumes, 1);
    EXPECT_EQ(west.summary().seat, 3);
    EXPECT_EQ(west.summary().team, 1);
    EXPECT_GT(west_shots_sent, 1); // it played on after the resume
    for (const auto* runner : {&south, &east, &west}) {
        EXPECT_TRUE(runner->summary().finished) << runner->summary().failure;
        EXPECT_EQ(runner->summary().games, 1);
        EXPECT_EQ(runner->summary().scores, south.summary().scores);
    }
    EXPECT_EQ(east.summary().wins, west.summary().wins); // partners
    EXPECT_EQ(east.summary().wins, south.summary().losses);
}

TEST(Doubles, FourQuickMatchPlayersShareOneRoom) {
    ServerProcess server(server_options({"--quick-match-bot", "0"})); // no bots: players only
    ASSERT_NE(server.port(), 0) << server.log();
    std::vector<std::unique_ptr<bots::Strategy>> strategies;
    std::vector<std::unique_ptr<bots::BotRunner>> players;
    for (int i = 0; i < 4; ++i) {
        strategies.push_back(test_strategy("random", static_cast<std::uint64_t>(i + 1)));
        auto config = config_for(server.url(), bots::JoinMode::Quick, "q" + std::to_string(i));
        config.quick_rule_set = proto::RuleSet::Freestyle;
        config.quick_seats = 4;
        players.push_back(std::make_unique<bots::BotRunner>(config, *strategies.back()));
        players.back()->start();
    }
    // A singles quick-match player of the same rule set is not paired with them.
    auto single_strategy = test_strategy("random", 9);
    auto single_config = config_for(server.url(), bots::JoinMode::Quick, "single");
    single_config.quick_rule_set = proto::RuleSet::Freestyle;
    bots::BotRunner single(single_config, *single_strategy);
    single.start();
    const auto deadline = Clock::now() + 20s;
    auto seated = [&] {
        for (const auto& p : players) {
            if (!p->room() || p->room()->phase == proto::Phase::Waiting) {
                return false;
            }
        }
        return true;
    };
    while (!seated() && Clock::now() < deadline) {
        for (auto& p : players) {
            p->step(2ms);
        }
        single.step(2ms);
    }
    ASSERT_TRUE(seated());
    std::set<int> seats;
    for (const auto& p : players) {
        EXPECT_EQ(p->room()->code, players[0]->room()->code);
        EXPECT_EQ(p->room()->seats.size(), 4u);
        seats.insert(p->room()->you);
        for (const auto& seat : p->room()->seats) {
            EXPECT_TRUE(seat.occupied);
            EXPECT_FALSE(seat.bot);
        }
    }
    EXPECT_EQ(seats, (std::set<int>{0, 1, 2, 3}));
    EXPECT_FALSE(single.room().has_value()); // still waiting for a singles opponent
}

TEST(Doubles, QuickMatchWaitRunsOutAndServerBotsTakeTheOtherThreeSeats) {
    ServerProcess server(server_options({"--quick-match-bot", "0.5"}));
    ASSERT_NE(server.port(), 0) << server.log();
    auto s0 = test_strategy("random", 1);
    auto config = config_for(server.url(), bots::JoinMode::Quick, "alone");
    // icf: a bot clearing a board does not end the game (freestyle ends at 170 points, which
    // a bot team can make before the last seat's first turn).
    config.quick_rule_set = proto::RuleSet::Icf;
    config.quick_seats = 4;
    bots::BotRunner alone(config, *s0);
    int shots_sent = 0;
    alone.on_shoot = [&](const proto::Shoot&) { ++shots_sent; };
    std::set<int> shooters; // seats of the shot results it saw
    alone.on_message = [&](const proto::ServerMessage& m) {
        if (const auto* r = std::get_if<proto::ShotResult>(&m)) {
            shooters.insert(r->seat);
        }
    };
    alone.start();
    // Play until every seat shot once (the bots included), or the time is up.
    const auto deadline = Clock::now() + 60s;
    while (shooters.size() < 4 && !alone.done() && Clock::now() < deadline) {
        alone.step(5ms);
    }
    ASSERT_TRUE(alone.room().has_value()) << alone.summary().failure;
    const proto::RoomState& room = *alone.room();
    ASSERT_EQ(room.seats.size(), 4u);
    for (std::size_t s = 0; s < 4; ++s) {
        EXPECT_TRUE(room.seats[s].occupied);
        EXPECT_EQ(room.seats[s].bot, static_cast<int>(s) != room.you) << "seat " << s;
    }
    EXPECT_GT(shots_sent, 0);
    EXPECT_EQ(shooters, (std::set<int>{0, 1, 2, 3})) << alone.summary().failure;
}

} // namespace
} // namespace carrom::integration
