// The client in a real networked match: carrom-server on 127.0.0.1 (ephemeral port), a
// carrom-bot that creates the room and breaks, this test watching as a spectator (what the
// server reports), and carrom-client joining as the second player. The client saves a
// screenshot once the break has been played and drawn at rest, with a JSON report of what it
// drew; the test checks the report against the server's room states and the PNG's pixels
// against the report (frame and surface colours, every piece's colour at its place). Every wait
// has a deadline; the children are ended with their process groups.

#include "carrom/client/screen_mapping.hpp"
#include "carrom/config.hpp"
#include "carrom/net/connection.hpp"
#include "client_program.hpp"
#include "support/child_process.hpp"

#include <SFML/Graphics/Image.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace carrom::client {
namespace {

using test_support::ChildProcess;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

std::string after_prefix(const std::optional<std::string>& line, const std::string& prefix) {
    return line ? line->substr(prefix.size()) : std::string();
}

// The room states a spectator receives (the server's word on where every piece rests).
class Spectator {
public:
    Spectator(const std::string& url, const std::string& code)
        : connection_(net::Connection::open(url)) {
        connection_->send(proto::Hello{proto::kProtocolVersion, "watcher", std::nullopt});
        code_ = code;
    }
    // Reads what arrived; joins the room once welcomed.
    void pump(std::chrono::milliseconds wait) {
        connection_->wait(wait);
        for (const proto::ServerMessage& m : connection_->poll()) {
            if (std::holds_alternative<proto::Welcome>(m)) {
                connection_->send(proto::JoinRoom{code_, proto::Role::Spectator});
            } else if (const auto* r = std::get_if<proto::RoomState>(&m)) {
                rooms_.push_back(*r);
            }
        }
    }
    const std::vector<proto::RoomState>& rooms() const { return rooms_; }

private:
    std::unique_ptr<net::Connection> connection_;
    std::string code_;
    std::vector<proto::RoomState> rooms_;
};

// Empty if every reported piece (id >= 0) is on the board in `room` at the same place and
// every piece on the board there is reported; else what differs.
std::string board_difference(const nlohmann::json& report, const proto::RoomState& room) {
    std::string diff;
    int matched = 0;
    for (const auto& b : report.at("bodies")) {
        const int id = b.at("id").get<int>();
        if (id < 0) {
            continue;
        }
        bool found = false;
        for (const proto::BoardBody& s : room.bodies) {
            if (s.id == id && !s.pocketed &&
                std::hypot(s.pos_px.x - b.at("x").get<double>(),
                           s.pos_px.y - b.at("y").get<double>()) < 0.05) {
                found = true;
            }
        }
        if (!found) {
            diff += " body " + std::to_string(id) + " elsewhere;";
        }
        ++matched;
    }
    // While aiming the client draws the striker where the shooter places it (id -1), not where
    // it last stopped.
    bool placed_striker = false;
    for (const auto& b : report.at("bodies")) {
        placed_striker = placed_striker || b.at("id").get<int>() < 0;
    }
    for (const proto::BoardBody& s : room.bodies) {
        if (s.pocketed || (placed_striker && s.kind == BodyKind::Striker)) {
            continue;
        }
        bool reported = false;
        for (const auto& b : report.at("bodies")) {
            reported = reported || b.at("id").get<int>() == s.id;
        }
        if (!reported) {
            diff += " body " + std::to_string(s.id) + " not drawn;";
        }
    }
    return diff;
}

bool colour_fits(const std::string& kind, sf::Color c) {
    if (kind == "black") {
        return c.r < 90 && c.g < 90 && c.b < 90;
    }
    if (kind == "white") {
        return c.r > 200 && c.g > 190 && c.b > 150;
    }
    if (kind == "queen") {
        return c.r > 150 && c.g < 80 && c.b < 90;
    }
    return c.r > 220 && c.g > 220 && c.b > 210; // striker
}

struct Outcome {
    int client_exit = -1;
    std::string code;
    nlohmann::json report;
    sf::Image image;
    std::vector<proto::RoomState> rooms;
    std::string client_log;
};

Outcome play_one_shot(const std::filesystem::path& dir) {
    Outcome o;
    const auto deadline = Clock::now() + 60s;
    ChildProcess server({CARROM_SERVER_PATH, "--host", "127.0.0.1", "--port", "0", "--shot-clock",
                         "0", "--log-level", "warn", "--data", "none"});
    const std::string port = after_prefix(
        server.wait_line(ChildProcess::Stream::Out, "listening on 127.0.0.1:", Clock::now() + 15s),
        "listening on 127.0.0.1:");
    if (port.empty()) {
        ADD_FAILURE() << "the server did not say where it listens";
        return o;
    }
    const std::string url = "ws://127.0.0.1:" + port;
    ChildProcess bot({CARROM_BOT_PATH, "--url", url, "--name", "Bot", "--create", "--rule-set",
                      "icf", "--strategy", "random", "--seed", "3", "--timeout", "60"});
    o.code = after_prefix(bot.wait_line(ChildProcess::Stream::Err, "room ", Clock::now() + 15s),
                          "room ");
    if (o.code.empty()) {
        ADD_FAILURE() << "the bot did not create a room";
        return o;
    }
    // Seated before the game starts, so it sees the room state after every shot.
    Spectator spectator(url, o.code);
    while (spectator.rooms().empty() && Clock::now() < deadline) {
        spectator.pump(50ms);
    }
    const std::string png = (dir / "shot.png").string();
    const std::string json = (dir / "shot.json").string();
    const std::vector<std::string> argv = client_argv({std::string("--url"),
                                                       url,
                                                       std::string("--name"),
                                                       std::string("Ana"),
                                                       std::string("--join"),
                                                       o.code,
                                                       std::string("--mute"),
                                                       std::string("--width"),
                                                       std::string("900"),
                                                       std::string("--height"),
                                                       std::string("900"),
                                                       std::string("--screenshot"),
                                                       png,
                                                       std::string("--report"),
                                                       json,
                                                       std::string("--frames"),
                                                       std::string("30"),
                                                       std::string("--after-shots"),
                                                       std::string("1"),
                                                       std::string("--timeout"),
                                                       std::string("45")});
    ChildProcess client(argv, {client_asan_options()});
    std::optional<int> exit;
    while (!exit && Clock::now() < deadline) {
        spectator.pump(20ms);
        exit = client.wait_exit(Clock::now() + 20ms);
    }
    spectator.pump(200ms); // a room state sent just before the screenshot
    o.client_exit = exit.value_or(-1);
    for (const std::string& line : client.lines(ChildProcess::Stream::Err)) {
        o.client_log += line + "\n";
    }
    for (const std::string& line : client.lines(ChildProcess::Stream::Out)) {
        o.client_log += line + "\n";
    }
    o.rooms = spectator.rooms();
    std::ifstream in(json);
    if (in) {
        o.report = nlohmann::json::parse(in, nullptr, false);
    }
    if (!o.image.loadFromFile(png)) {
        ADD_FAILURE() << "no screenshot at " << png;
    }
    return o;
}

TEST(NetworkMatch, ClientShowsTheBoardTheServerReportsAfterABotShot) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("carrom-client-net-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const Outcome o = play_one_shot(dir);
    std::filesystem::remove_all(dir);
    ASSERT_EQ(o.client_exit, 0) << o.client_log;
    ASSERT_TRUE(o.report.is_object()) << o.client_log;
    EXPECT_NE(o.client_log.find("room " + o.code), std::string::npos) << o.client_log;

    // The report: our room, seat 1 (the bot created it), the break played.
    EXPECT_EQ(o.report.at("room"), o.code);
    EXPECT_EQ(o.report.at("you"), 1);
    EXPECT_EQ(o.report.at("flipped"), true); // seat 1 shoots from the top baseline
    EXPECT_GE(o.report.at("shots_seen").get<int>(), 1);
    EXPECT_GE(o.report.at("turn").get<int>(), 2);

    // What it drew is a board the server reported after the break.
    bool matched = false;
    std::string differences;
    for (const proto::RoomState& r : o.rooms) {
        const std::string diff = board_difference(o.report, r);
        matched = matched || (r.turn >= 2 && diff.empty());
        differences += "turn " + std::to_string(r.turn) + " phase " +
                       std::string(proto::to_string(r.phase)) + ":" + diff + "\n";
    }
    EXPECT_TRUE(matched) << "no room state after the break has the pieces where the client drew "
                            "them:\n"
                         << differences;

    // The pixels: frame, surface, and every piece's colour at its centre (unless a message
    // covers it or a piece drawn later sits on it).
    ASSERT_EQ(o.image.getSize().x, 900u);
    const PhysicsConfig physics{};
    const ScreenMapping m = make_mapping({o.report.at("board").at("x").get<double>(),
                                          o.report.at("board").at("y").get<double>(),
                                          o.report.at("board").at("side").get<double>(),
                                          o.report.at("board").at("side").get<double>()},
                                         physics.board_size_px, rules::Side::Top);
    auto pixel = [&o](Vec2 p) {
        return o.image.getPixel(static_cast<unsigned>(p.x), static_cast<unsigned>(p.y));
    };
    const sf::Color frame = pixel(m.to_screen({17.0, 300.0}));
    EXPECT_GT(frame.r, frame.g);
    EXPECT_GT(frame.g, frame.b);
    EXPECT_LT(frame.r, 170);
    const sf::Color surface = pixel(m.to_screen({200.0, 150.0}));
    EXPECT_GT(surface.r, 190);
    EXPECT_GT(surface.r, surface.b + 50);
    const auto& bodies = o.report.at("bodies");
    const auto& overlay = o.report.at("overlay");
    int checked = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const auto& b = bodies[i];
        const Vec2 s{b.at("screen_x").get<double>(), b.at("screen_y").get<double>()};
        if (!overlay.is_null() && s.x >= overlay.at("x").get<double>() - 20.0 &&
            s.x < overlay.at("x").get<double>() + overlay.at("w").get<double>() + 20.0 &&
            s.y >= overlay.at("y").get<double>() - 20.0 &&
            s.y < overlay.at("y").get<double>() + overlay.at("h").get<double>() + 20.0) {
            continue;
        }
        bool covered = false;
        for (std::size_t k = i + 1; k < bodies.size(); ++k) {
            covered = covered || std::hypot(bodies[k].at("screen_x").get<double>() - s.x,
                                            bodies[k].at("screen_y").get<double>() - s.y) <
                                     m.length_to_screen(physics.striker_radius_px);
        }
        if (covered || b.at("alpha").get<double>() < 1.0) {
            continue;
        }
        const std::string kind = b.at("kind").get<std::string>();
        const sf::Color c = pixel(s);
        EXPECT_TRUE(colour_fits(kind, c))
            << kind << " " << b.at("id") << " at (" << s.x << ", " << s.y << ") shows " << int{c.r}
            << "," << int{c.g} << "," << int{c.b};
        ++checked;
    }
    EXPECT_GE(checked, 8);
}

} // namespace
} // namespace carrom::client
