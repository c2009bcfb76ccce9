// The match API's answers (server/src/match_api.hpp) against a real SQLite store in a temporary
// directory: the query and id checks, 404, an empty list, and 503 without a store. Whole matches
// through a real carrom-server are in tests/integration/store_process_test.cpp.
#include "match_api.hpp"
#include "store/sqlite_match_store.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <stdlib.h>

namespace carrom::server {
namespace {

namespace fs = std::filesystem;

class MatchApiTest : public ::testing::Test {
protected:
    MatchApiTest() {
        std::string pattern = (fs::temp_directory_path() / "carrom_match_api_XXXXXX").string();
        dir_ = ::mkdtemp(pattern.data());
        auto opened = store::SqliteMatchStore::open(dir_ + "/c.db");
        EXPECT_FALSE(opened.error);
        store_ = std::move(opened.store);
    }
    ~MatchApiTest() override {
        store_.reset();
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    std::string code_of(const MatchApiAnswer& answer) {
        return nlohmann::json::parse(answer.body)["error"]["code"];
    }

    std::string dir_;
    std::unique_ptr<store::SqliteMatchStore> store_;
};

TEST_F(MatchApiTest, RoutesOnlyTheMatchPaths) {
    EXPECT_TRUE(is_match_api_target("/matches?player=a"));
    EXPECT_TRUE(is_match_api_target("/matches/abc"));
    EXPECT_FALSE(is_match_api_target("/matchesx"));
    EXPECT_FALSE(is_match_api_target("/index.html?x=/matches/"));
}

TEST_F(MatchApiTest, BadIdsAndQueriesAre400UnknownIdsAre404) {
    for (const std::string& target : std::vector<std::string>{
             "/matches/", "/matches/a%20b", "/matches/a.b", "/matches/" + std::string(65, 'a')}) {
        const auto answer = answer_match_api(store_.get(), target);
        EXPECT_EQ(answer.status, 400) << target;
        EXPECT_EQ(code_of(answer), "bad_match_id") << target;
    }
    for (const std::string& target : std::vector<std::string>{
             "/matches", "/matches?limit=5", "/matches?player=a&limit=0",
             "/matches?player=a&limit=101", "/matches?player=a&limit=5x", "/matches?player=%zz",
             "/matches?player=%4", "/matches?player=a&sort=new",
             "/matches?player=", "/matches/abc?x=1"}) {
        const auto answer = answer_match_api(store_.get(), target);
        EXPECT_EQ(answer.status, 400) << target;
        EXPECT_EQ(code_of(answer), "bad_query") << target;
    }
    const auto unknown = answer_match_api(store_.get(), "/matches/abc");
    EXPECT_EQ(unknown.status, 404);
    EXPECT_EQ(code_of(unknown), "unknown_match");
}

TEST_F(MatchApiTest, AListDecodesThePlayerName) {
    const auto answer = answer_match_api(store_.get(), "/matches?player=Ann+Lee%21&limit=100");
    ASSERT_EQ(answer.status, 200) << answer.body;
    const auto json = nlohmann::json::parse(answer.body);
    EXPECT_EQ(json["format"], 1);
    EXPECT_EQ(json["player"], "Ann Lee!");
    EXPECT_TRUE(json["matches"].empty());
}

TEST_F(MatchApiTest, AListGivesEverySeatsTeam) {
    proto::MatchCreated doubles;
    doubles.match_id = "dbl1";
    doubles.room_code = "DBXAAA";
    doubles.rules.seat_count = 4;
    doubles.seats = {{"Ann", false}, {"Bo", false}, {"Bot (easy)", true}, {"Cy", false}};
    doubles.time_ms = 1700000000000;
    proto::MatchCreated singles = doubles;
    singles.match_id = "sgl1";
    singles.rules.seat_count = 2;
    singles.seats = {{"Ann", false}, {"Cy", false}};
    singles.time_ms = 1700000001000;
    store_->create(doubles);
    store_->create(singles);
    ASSERT_TRUE(store_->flush(std::chrono::milliseconds(5000)));
    const auto answer = answer_match_api(store_.get(), "/matches?player=Cy");
    ASSERT_EQ(answer.status, 200) << answer.body;
    const auto matches = nlohmann::json::parse(answer.body)["matches"];
    ASSERT_EQ(matches.size(), 2U);
    EXPECT_EQ(matches[0]["id"], "sgl1"); // newest first
    EXPECT_EQ(matches[0]["teams"], nlohmann::json::parse("[0, 1]"));
    EXPECT_EQ(matches[0]["replay"], "/#/replay/sgl1"); // the web client's replay page
    EXPECT_EQ(matches[1]["players"],
              nlohmann::json::parse(R"j(["Ann", "Bo", "Bot (easy)", "Cy"])j"));
    EXPECT_EQ(matches[1]["teams"], nlohmann::json::parse("[0, 1, 0, 1]"));
}

TEST(MatchApi, WithoutAStoreEveryRequestIs503) {
    for (const char* target : {"/matches/abc", "/matches?player=a", "/matches/"}) {
        const auto answer = answer_match_api(nullptr, target);
        EXPECT_EQ(answer.status, 503);
        EXPECT_EQ(nlohmann::json::parse(answer.body)["error"]["code"], "store_disabled");
    }
}

} // namespace
} // namespace carrom::server
