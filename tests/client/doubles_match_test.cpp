// The client in real doubles rooms: carrom-server on 127.0.0.1 with server bots, carrom-client
// --autoplay under Xvfb playing its turns through the mouse input path, until a number of
// strokes has been played and drawn at rest (then a screenshot and its report).
// - From a side seat: this test plays seat 0 itself over a plain connection (it creates the
//   room with bots in seats 2 and 3 and shoots straight up the board from a free spot), the
//   client joins by code and takes seat 1, the right side: its view is turned a quarter, and
//   its shots from the right baseline are accepted.
// - `--seats 4 --vs-bot`: the client creates a doubles room with three server bots.
// Every wait has a deadline; the children are ended with their process groups.

#include "carrom/client/screen_mapping.hpp"
#include "carrom/config.hpp"
#include "carrom/net/connection.hpp"
#include "client_program.hpp"
#include "support/child_process.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include <SFML/Graphics/Image.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace carrom::client {
namespace {

using test_support::ChildProcess;
using test_support::ServerProcess;
using test_support::TempDir;
using Clock = std::chrono::steady_clock;
using Json = nlohmann::json;
using namespace std::chrono_literals;

// A player on seat 0 over a plain connection: creates the room, then on each of its turns (a
// room state saying seat 0 aims) shoots straight up from the first free spot of its baseline.
// It counts the strokes each seat played (shot results).
class SeatZero {
public:
    explicit SeatZero(const std::string& url) : connection_(net::Connection::open(url)) {
        connection_->send(proto::Hello{proto::kProtocolVersion, "Asha", std::nullopt});
    }
    void pump(std::chrono::milliseconds wait) {
        connection_->wait(wait);
        for (const proto::ServerMessage& m : connection_->poll()) {
            if (std::holds_alternative<proto::Welcome>(m)) {
                proto::CreateRoom create;
                // icf to 25 points: a board won gives at most 12, so no game ends within the
                // client's 16 strokes (freestyle ends at 170, which a team can make in fewer).
                create.rule_set = proto::RuleSet::Icf;
                create.seats = 4;
                proto::BotSeat bots;
                bots.level = proto::BotLevel::Easy;
                bots.seats = {2, 3};
                create.bot = bots;
                connection_->send(create);
            } else if (const auto* r = std::get_if<proto::RoomState>(&m)) {
                code_ = r->code;
                seats_ = static_cast<int>(r->seats.size());
                sides_.clear();
                for (const proto::SeatInfo& s : r->seats) {
                    sides_.push_back(std::string(proto::baseline_name(s.baseline)));
                }
                scores_ = r->scores;
                if (r->phase == proto::Phase::Aiming && r->to_play == 0 && shot_turn_ != r->turn) {
                    shoot(*r);
                }
            } else if (const auto* s = std::get_if<proto::ShotResult>(&m)) {
                ++strokes_[s->seat];
                scores_ = s->scores;
            } else if (const auto* e = std::get_if<proto::Error>(&m)) {
                errors_ += e->code + ": " + e->message + "\n";
            }
        }
    }
    const std::string& code() const { return code_; }
    int seats() const { return seats_; }
    const std::vector<std::string>& sides() const { return sides_; }
    const std::map<int, int>& strokes() const { return strokes_; }
    const std::vector<int>& scores() const { return scores_; }
    const std::string& errors() const { return errors_; }

private:
    void shoot(const proto::RoomState& r) {
        const PhysicsConfig physics;
        // From the middle outwards in 1 px steps: some spot of the baseline is always free.
        std::vector<double> spots;
        for (int d = 0; d <= 187; ++d) {
            spots.push_back(300.0 + d);
            spots.push_back(300.0 - d);
        }
        for (const double x : spots) {
            const Vec2 at{x, physics.board_size_px - physics.baseline_offset_px};
            bool free = true;
            for (const proto::BoardBody& b : r.bodies) {
                const double reach = physics.striker_radius_px + physics.radius(b.kind) + 0.5;
                free = free &&
                       (b.pocketed || b.kind == BodyKind::Striker || length(b.pos_px - at) > reach);
            }
            if (free) {
                connection_->send(proto::Shoot{r.turn, x, -std::numbers::pi / 2.0, 9.0});
                shot_turn_ = r.turn;
                return;
            }
        }
    }

    std::unique_ptr<net::Connection> connection_;
    std::string code_;
    int seats_ = 0;
    std::vector<std::string> sides_;
    std::map<int, int> strokes_;
    std::vector<int> scores_;
    std::string errors_;
    int shot_turn_ = -1;
};

ServerProcess::Options server_options() {
    return {
        CARROM_SERVER_PATH,
        "none",
        {"--shot-clock", "0", "--time-scale", "25", "--bot-think-ms", "50", "--log-level", "info"},
        {},
        0};
}

// The pieces of the report are drawn where the turned view puts them, in their colours.
void expect_pieces_drawn(const Json& report, const sf::Image& image, rules::Side side) {
    const ScreenMapping m =
        make_mapping({report["board"]["x"].get<double>(), report["board"]["y"].get<double>(),
                      report["board"]["side"].get<double>(), report["board"]["side"].get<double>()},
                     600.0, side);
    int checked = 0;
    for (const Json& b : report["bodies"]) {
        const Vec2 screen = m.to_screen({b["x"].get<double>(), b["y"].get<double>()});
        EXPECT_NEAR(screen.x, b["screen_x"].get<double>(), 1e-6);
        EXPECT_NEAR(screen.y, b["screen_y"].get<double>(), 1e-6);
        if (b["kind"] != "black" || b["scale"] != 1.0) {
            continue;
        }
        const sf::Color c =
            image.getPixel(static_cast<unsigned>(screen.x), static_cast<unsigned>(screen.y));
        checked += c.r < 90 && c.g < 90 && c.b < 90 ? 1 : 0;
    }
    EXPECT_GE(checked, 1) << "no black coin drawn at its turned place";
}

TEST(DoublesMatch, ClientOnTheRightSideAutoplaysWithAPlayerAndTwoServerBots) {
    TempDir dir("carrom_doubles_client");
    ServerProcess server(server_options());
    ASSERT_TRUE(server.start()) << server.log();
    SeatZero asha(server.url());
    const auto deadline = Clock::now() + 120s;
    while (asha.code().empty() && Clock::now() < deadline) {
        asha.pump(20ms);
    }
    ASSERT_FALSE(asha.code().empty()) << asha.errors() << server.log();
    ChildProcess client(client_argv({"--url", server.url(), "--name", "Ravi", "--join", asha.code(),
                                     "--mute", "--autoplay", "easy", "--screenshot",
                                     dir.file("right.png"), "--report", dir.file("right.json"),
                                     "--frames", "30", "--after-shots", "16", "--timeout", "100"}),
                        {client_asan_options()});
    std::optional<int> exit;
    while (!exit && Clock::now() < deadline) {
        asha.pump(20ms);
        exit = client.wait_exit(Clock::now() + 10ms);
    }
    ASSERT_TRUE(exit) << client.output();
    ASSERT_EQ(*exit, 0) << client.output() << asha.errors() << server.log();

    EXPECT_EQ(asha.seats(), 4);
    EXPECT_EQ(asha.sides(), (std::vector<std::string>{"bottom", "right", "top", "left"}));
    // Every seat played, the client (seat 1, the right side) included: its shots from the right
    // baseline were accepted by the server.
    for (int seat = 0; seat < 4; ++seat) {
        EXPECT_GE(asha.strokes().count(seat) ? asha.strokes().at(seat) : 0, 1) << seat;
    }
    ASSERT_EQ(asha.scores().size(), 4u);
    EXPECT_EQ(asha.scores()[0], asha.scores()[2]); // partners share the team's score
    EXPECT_EQ(asha.scores()[1], asha.scores()[3]);

    std::ifstream in(dir.file("right.json"));
    const Json report = Json::parse(in, nullptr, false);
    ASSERT_TRUE(report.is_object()) << client.output();
    EXPECT_EQ(report["you"], 1);
    EXPECT_EQ(report["bottom_side"], "right");
    EXPECT_EQ(report["scores"].size(), 4u);
    EXPECT_GE(report["shots_seen"].get<int>(), 9);
    // The own strokes were predicted, and the server's streams confirmed each one (same build:
    // exactly, up to the snapshots' 0.01 px rounding).
    EXPECT_GE(report["prediction"]["strokes"].get<int>(), 1);
    EXPECT_EQ(report["prediction"]["corrections"], 0);
    EXPECT_LT(report["prediction"]["max_difference_px"].get<double>(), 0.01);
    sf::Image image;
    ASSERT_TRUE(image.loadFromFile(dir.file("right.png")));
    expect_pieces_drawn(report, image, rules::Side::Right);
}

TEST(DoublesMatch, VsBotWithFourSeatsPlaysWithThreeServerBots) {
    TempDir dir("carrom_doubles_vs_bot");
    ServerProcess server(server_options());
    ASSERT_TRUE(server.start()) << server.log();
    ChildProcess client(client_argv({"--url",
                                     server.url(),
                                     "--name",
                                     "Asha",
                                     "--vs-bot",
                                     "easy",
                                     "--seats",
                                     "4",
                                     "--rules",
                                     "icf", // 25 points: no game end within 8 strokes
                                     "--mute",
                                     "--autoplay",
                                     "easy",
                                     "--screenshot",
                                     dir.file("bots.png"),
                                     "--report",
                                     dir.file("bots.json"),
                                     "--frames",
                                     "30",
                                     "--after-shots",
                                     "8",
                                     "--timeout",
                                     "100"}),
                        {client_asan_options()});
    const auto exit = client.wait_exit(Clock::now() + 110s);
    ASSERT_TRUE(exit) << client.output();
    ASSERT_EQ(*exit, 0) << client.output() << server.log();
    std::ifstream in(dir.file("bots.json"));
    const Json report = Json::parse(in, nullptr, false);
    ASSERT_TRUE(report.is_object()) << client.output();
    EXPECT_EQ(report["you"], 0);
    EXPECT_EQ(report["bottom_side"], "bottom");
    ASSERT_EQ(report["scores"].size(), 4u);
    EXPECT_EQ(report["scores"][0], report["scores"][2]);
    EXPECT_EQ(report["scores"][1], report["scores"][3]);
    EXPECT_GE(report["shots_seen"].get<int>(), 8);
    // The own strokes were predicted, and the server's streams confirmed each one (same build:
    // exactly, up to the snapshots' 0.01 px rounding).
    EXPECT_GE(report["prediction"]["strokes"].get<int>(), 1);
    EXPECT_EQ(report["prediction"]["corrections"], 0);
    EXPECT_LT(report["prediction"]["max_difference_px"].get<double>(), 0.01);
    sf::Image image;
    ASSERT_TRUE(image.loadFromFile(dir.file("bots.png")));
    expect_pieces_drawn(report, image, rules::Side::Bottom);
}

} // namespace
} // namespace carrom::client
