#include "font.hpp"

#include <cstdlib>
#include <filesystem>

namespace carrom::client::app {

std::vector<std::string> font_candidates() {
    std::vector<std::string> out;
    if (const char* env = std::getenv("CARROM_FONT"); env != nullptr && *env != '\0') {
        out.emplace_back(env);
    }
    for (const char* p :
         {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
          "/usr/share/fonts/dejavu/DejaVuSans.ttf",
          "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",
          "/usr/local/share/fonts/DejaVuSans.ttf", "/Library/Fonts/DejaVuSans.ttf"}) {
        out.emplace_back(p);
    }
    return out;
}

bool load_font(sf::Font& font, std::string& error) {
    std::error_code ec;
    for (const std::string& path : font_candidates()) {
        if (std::filesystem::is_regular_file(path, ec) && font.loadFromFile(path)) {
            return true;
        }
    }
    error = "No usable font found. Install the DejaVu fonts (Debian: apt-get install "
            "fonts-dejavu-core) or set CARROM_FONT to a .ttf file. Tried:";
    for (const std::string& path : font_candidates()) {
        error += "\n  " + path;
    }
    return false;
}

} // namespace carrom::client::app
