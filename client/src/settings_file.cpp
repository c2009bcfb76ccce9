#include "carrom/client/settings_file.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace carrom::client {

std::string settings_path(const char* xdg_config_home, const char* home) {
    if (xdg_config_home != nullptr && *xdg_config_home != '\0') {
        return std::string(xdg_config_home) + "/carrom/settings.json";
    }
    if (home != nullptr && *home != '\0') {
        return std::string(home) + "/.config/carrom/settings.json";
    }
    return "";
}

SettingsLoad load_settings(const std::string& path) {
    SettingsLoad out;
    std::ifstream in(path);
    if (!in) {
        return out; // no file yet: the defaults
    }
    std::stringstream text;
    text << in.rdbuf();
    const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        out.problem = path + " is not a JSON object; the default settings apply.";
        return out;
    }
    Settings& s = out.settings;
    if (const auto v = j.find("volume"); v != j.end()) {
        if (v->is_number_integer() && v->get<int>() >= 0 && v->get<int>() <= 100) {
            s.volume = v->get<int>();
        } else {
            out.problem = path + ": volume must be a whole percent from 0 to 100.";
        }
    }
    const auto flag = [&](const char* key, bool& field) {
        if (const auto v = j.find(key); v != j.end()) {
            if (v->is_boolean()) {
                field = v->get<bool>();
            } else {
                out.problem = path + ": " + key + " must be true or false.";
            }
        }
    };
    flag("muted", s.muted);
    flag("reduced_motion", s.reduced_motion);
    flag("coached", s.coached);
    return out;
}

std::string save_settings(const std::string& path, const Settings& s) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    std::ofstream out(path);
    out << nlohmann::json{{"volume", s.volume},
                          {"muted", s.muted},
                          {"reduced_motion", s.reduced_motion},
                          {"coached", s.coached}}
               .dump(1)
        << "\n";
    if (!out) {
        return "Could not write the settings to " + path + ".";
    }
    return "";
}

} // namespace carrom::client
