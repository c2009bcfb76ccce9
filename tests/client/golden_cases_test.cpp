// The golden cases of tests/golden/ replayed through the desktop client's logic: the files were
// written by carrom-golden from this logic, so a change to it that is not regenerated (and then
// followed by web/js, which tests/web/golden_test.mjs replays the same files through) fails here.
#include "carrom/golden/aim_cases.hpp"
#include "carrom/golden/golden_json.hpp"
#include "carrom/golden/interpolation_cases.hpp"
#include "carrom/golden/model_cases.hpp"
#include "carrom/golden/word_cases.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace carrom::golden {
namespace {

namespace fs = std::filesystem;

fs::path golden_dir() {
    const char* source = std::getenv("CARROM_SOURCE_DIR");
    return fs::path(source != nullptr ? source : ".") / "tests" / "golden";
}

nlohmann::json read_case(const fs::path& path) {
    const auto text = read_text(path.string());
    EXPECT_TRUE(text.has_value()) << path;
    return text ? nlohmann::json::parse(*text) : nlohmann::json();
}

std::vector<fs::path> cases_in(const std::string& folder) {
    std::vector<fs::path> out;
    for (const auto& entry : fs::directory_iterator(golden_dir() / folder)) {
        if (entry.path().extension() == ".json") {
            out.push_back(entry.path());
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(GoldenJson, FirstDifferenceNamesWhereNumbersOrTextDiffer) {
    EXPECT_EQ(first_difference({{"a", {1.0, "x"}}}, {{"a", {1.0 + 1e-7, "x"}}}), "");
    EXPECT_EQ(first_difference({{"a", {1.0, "x"}}}, {{"a", {1.001, "x"}}}),
              "$.a[0]: expected 1.0, got 1.001");
    EXPECT_EQ(first_difference({{"a", "x"}}, {{"a", "y"}}), "$.a: expected \"x\", got \"y\"");
    EXPECT_EQ(first_difference({{"a", 1}}, {{"a", 1}, {"b", 2}}), "$.b: not expected (2)");
    EXPECT_EQ(first_difference({{"a", nullptr}}, {{"a", 0}}), "$.a: expected null, got 0");
}

TEST(GoldenCases, ModelStreamsGiveTheRecordedStates) {
    const std::vector<fs::path> files = cases_in("model");
    ASSERT_EQ(files.size(), 3u); // cues.json, doubles.json, singles.json
    for (const fs::path& file : files) {
        const nlohmann::json c = read_case(file);
        const auto stream =
            read_text((file.parent_path() / c.at("stream").get<std::string>()).string());
        ASSERT_TRUE(stream.has_value()) << file;
        EXPECT_EQ(first_difference(c.at("expected"), model_steps(parse_stream(*stream))), "")
            << file;
    }
}

TEST(GoldenCases, InterpolationAndPlayoutGiveTheRecordedBoards) {
    const std::vector<fs::path> files = cases_in("interpolation");
    ASSERT_EQ(files.size(), 3u); // every_change.json, playout.json, regular.json
    for (const fs::path& file : files) {
        const nlohmann::json c = read_case(file);
        const nlohmann::json actual = file.filename() == "playout.json"
                                          ? replay_playout(c.at("input"))
                                          : replay_interpolation(c.at("input"));
        EXPECT_EQ(first_difference(c.at("expected"), actual), "") << file;
    }
}

TEST(GoldenCases, AimGesturesGiveTheRecordedShots) {
    const std::vector<fs::path> files = cases_in("aim");
    ASSERT_EQ(files.size(), 4u); // one per side
    for (const fs::path& file : files) {
        const nlohmann::json c = read_case(file);
        EXPECT_EQ(first_difference(c.at("expected"), replay_aim(c.at("input"))), "") << file;
    }
}

TEST(GoldenCases, PlainWordsAreTheRecordedOnes) {
    const nlohmann::json c = read_case(golden_dir() / "words" / "words.json");
    EXPECT_EQ(first_difference(c.at("expected"), replay_words(c.at("input"))), "");
}

// The generator's inputs are made the same way every time: regenerating without a change to the
// logic changes no file.
TEST(GoldenCases, InputsAreReproducible) {
    for (const char* side : {"bottom", "right", "top", "left"}) {
        const nlohmann::json c = read_case(golden_dir() / "aim" / (std::string(side) + ".json"));
        EXPECT_EQ(first_difference(c.at("input"), aim_input(side)), "") << side;
    }
    EXPECT_EQ(first_difference(read_case(golden_dir() / "words" / "words.json").at("input"),
                               words_input()),
              "");
}

} // namespace
} // namespace carrom::golden
