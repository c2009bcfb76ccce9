#include "carrom/client/settings_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace carrom::client {
namespace {

std::filesystem::path temp_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("carrom_settings_" + name);
    std::filesystem::remove_all(dir);
    return dir;
}

TEST(SettingsFile, PathFollowsXdgThenHome) {
    EXPECT_EQ(settings_path("/x/cfg", "/home/a"), "/x/cfg/carrom/settings.json");
    EXPECT_EQ(settings_path("", "/home/a"), "/home/a/.config/carrom/settings.json");
    EXPECT_EQ(settings_path(nullptr, "/home/a"), "/home/a/.config/carrom/settings.json");
    EXPECT_EQ(settings_path(nullptr, nullptr), "");
}

TEST(SettingsFile, MissingFileGivesDefaults) {
    const SettingsLoad l = load_settings(temp_dir("missing") / "settings.json");
    EXPECT_EQ(l.settings, Settings{});
    EXPECT_EQ(l.problem, "");
}

TEST(SettingsFile, SavedSettingsComeBack) {
    const auto path = (temp_dir("round") / "carrom" / "settings.json").string();
    const Settings s{35, true, true, true};
    EXPECT_EQ(save_settings(path, s), "");
    const SettingsLoad l = load_settings(path);
    EXPECT_EQ(l.settings, s);
    EXPECT_EQ(l.problem, "");
}

TEST(SettingsFile, DamagedFileGivesDefaultsAndASentence) {
    const auto dir = temp_dir("damaged");
    std::filesystem::create_directories(dir);
    const auto path = (dir / "settings.json").string();
    std::ofstream(path) << "{not json";
    SettingsLoad l = load_settings(path);
    EXPECT_EQ(l.settings, Settings{});
    EXPECT_EQ(l.problem, path + " is not a JSON object; the default settings apply.");
    std::ofstream(path) << R"({"volume": 140, "muted": true})";
    l = load_settings(path);
    EXPECT_EQ(l.settings.volume, 80);
    EXPECT_TRUE(l.settings.muted);
    EXPECT_EQ(l.problem, path + ": volume must be a whole percent from 0 to 100.");
}

} // namespace
} // namespace carrom::client
