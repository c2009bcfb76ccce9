#pragma once
// The desktop client's settings (web/js/settings.js keeps the page's): sound volume and mute,
// reduced motion (pocketed pieces vanish at once) and whether the first-game tips were seen.
// Kept as JSON in $XDG_CONFIG_HOME/carrom/settings.json ($HOME/.config when XDG_CONFIG_HOME is
// unset or empty). A missing file gives the defaults; a damaged one the defaults plus one
// sentence saying why; unknown fields are ignored.

#include <string>

namespace carrom::client {

struct Settings {
    int volume = 80; // percent, 0..100
    bool muted = false;
    bool reduced_motion = false;
    bool coached = false; // the first-game tips were seen to the end or skipped
    bool operator==(const Settings&) const = default;
};

// The settings file's path from the environment's values (empty: unset); empty when neither is set.
std::string settings_path(const char* xdg_config_home, const char* home);

struct SettingsLoad {
    Settings settings;
    std::string problem; // empty: read, or no file yet
};
SettingsLoad load_settings(const std::string& path);
// Writes the file (making its directory); empty on success, else one sentence.
std::string save_settings(const std::string& path, const Settings& settings);

} // namespace carrom::client
