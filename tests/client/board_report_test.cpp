#include "carrom/client/board_report.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace carrom::client {
namespace {

MatchView two_seats() {
    MatchView v;
    v.in_room = true;
    v.code = "ABC234";
    v.you = 1;
    v.turn = 3;
    v.phase = proto::Phase::Aiming;
    v.seats.resize(2);
    v.seats[0].score = 4;
    v.seats[1].score = 1;
    return v;
}

TEST(BoardReport, RoomTurnAndLayout) {
    const ScreenMapping m = make_mapping({54.0, 68.0, 792.0, 792.0}, 600.0);
    const auto j = nlohmann::json::parse(
        board_report_json(two_seats(), {}, m, {900.0, 900.0, 2, std::nullopt, {}}));
    EXPECT_EQ(j.at("room"), "ABC234");
    EXPECT_EQ(j.at("you"), 1);
    EXPECT_EQ(j.at("turn"), 3);
    EXPECT_EQ(j.at("phase"), "aiming");
    EXPECT_EQ(j.at("flipped"), false);
    EXPECT_EQ(j.at("bottom_side"), "bottom");
    EXPECT_EQ(j.at("window").at("w"), 900.0);
    EXPECT_EQ(j.at("board").at("x"), 54.0);
    EXPECT_EQ(j.at("board").at("y"), 68.0);
    EXPECT_DOUBLE_EQ(j.at("board").at("side").get<double>(), 792.0);
    EXPECT_EQ(j.at("shots_seen"), 2);
    EXPECT_EQ(j.at("scores"), nlohmann::json::array({4, 1}));
    EXPECT_TRUE(j.at("bodies").empty());
    EXPECT_TRUE(j.at("overlay").is_null());
}

TEST(BoardReport, BodiesInBoardAndWindowPxThroughTheTurnedView) {
    const ScreenMapping m = make_mapping({100.0, 50.0, 300.0, 300.0}, 600.0, rules::Side::Top);
    const std::vector<RenderedBody> bodies{
        {0, BodyKind::Queen, {300.0, 300.0}, 1.0, 1.0, false},
        {7, BodyKind::White, {100.0, 500.0}, 0.5, 0.25, true},
        {-1, BodyKind::Striker, {300.0, 520.0}, 1.0, 1.0, false}};
    const auto j = nlohmann::json::parse(
        board_report_json(two_seats(), bodies, m, {500.0, 400.0, 0, std::nullopt, {}}));
    ASSERT_EQ(j.at("bodies").size(), 3u);
    const auto& queen = j.at("bodies")[0];
    EXPECT_EQ(queen.at("kind"), "queen");
    EXPECT_DOUBLE_EQ(queen.at("screen_x").get<double>(), 250.0);
    EXPECT_DOUBLE_EQ(queen.at("screen_y").get<double>(), 200.0);
    const auto& white = j.at("bodies")[1];
    EXPECT_EQ(white.at("id"), 7);
    EXPECT_EQ(white.at("kind"), "white");
    EXPECT_DOUBLE_EQ(white.at("x").get<double>(), 100.0);
    // Half a turn: board (100, 500) shows at board (500, 100), scaled by 0.5.
    EXPECT_DOUBLE_EQ(white.at("screen_x").get<double>(), 100.0 + 250.0);
    EXPECT_DOUBLE_EQ(white.at("screen_y").get<double>(), 50.0 + 50.0);
    EXPECT_DOUBLE_EQ(white.at("scale").get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(white.at("alpha").get<double>(), 0.25);
    EXPECT_EQ(j.at("bodies")[2].at("id"), -1);
    EXPECT_EQ(j.at("bodies")[2].at("kind"), "striker");
    EXPECT_EQ(j.at("flipped"), true);
    EXPECT_EQ(j.at("bottom_side"), "top");
}

TEST(BoardReport, OverlayRect) {
    const ScreenMapping m = make_mapping({0.0, 0.0, 600.0, 600.0}, 600.0);
    ReportContext c{600.0, 700.0, 1, Rect{10.0, 20.0, 30.0, 40.0}, {}, "null", nullptr};
    const auto j = nlohmann::json::parse(board_report_json(two_seats(), {}, m, c));
    EXPECT_EQ(j.at("overlay"),
              (nlohmann::json{{"x", 10.0}, {"y", 20.0}, {"w", 30.0}, {"h", 40.0}}));
}

TEST(BoardReport, PredictionFigures) {
    const ScreenMapping m = make_mapping({0.0, 0.0, 600.0, 600.0}, 600.0);
    ReportContext c{600.0, 700.0, 1, std::nullopt, {}, "null", nullptr};
    c.prediction.strokes = 7;
    c.prediction.corrections = 2;
    c.prediction.max_difference_px = 5.5;
    const auto j = nlohmann::json::parse(board_report_json(two_seats(), {}, m, c));
    EXPECT_EQ(j.at("prediction"),
              (nlohmann::json{{"strokes", 7}, {"corrections", 2}, {"max_difference_px", 5.5}}));
}

TEST(BoardReport, FinalStateNamesTheEndByItsRuleCode) {
    MatchView v = two_seats();
    v.phase = proto::Phase::GameOver;
    v.result = GameResult{0, "score", {25, 11}, {"Ana", "Ben"}, "target_points"};
    const auto j = nlohmann::json::parse(final_state_json(v, {}));
    EXPECT_EQ(j.at("reason"), "target_points");
    EXPECT_EQ(j.at("winner"), 0);
    EXPECT_EQ(j.at("scores"), nlohmann::json::array({25, 11}));
}

TEST(BoardReport, FinalStateNamesTheEndByGameEndsReasonWithoutARuleCode) {
    MatchView v = two_seats();
    v.phase = proto::Phase::GameOver;
    v.result = GameResult{1, "left", {3, 5}, {"Ana", "Ben"}};
    EXPECT_EQ(nlohmann::json::parse(final_state_json(v, {})).at("reason"), "left");
    v.result->rule = "forfeit";
    EXPECT_EQ(nlohmann::json::parse(final_state_json(v, {})).at("reason"), "forfeit");
}

} // namespace
} // namespace carrom::client
