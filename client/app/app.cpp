#include "app.hpp"

#include "app_window.hpp"
#include "font.hpp"

#include <SFML/Graphics.hpp>

#include <iostream>

namespace carrom::client::app {

int run_app(const AppOptions& options) {
    sf::Font font;
    std::string error;
    if (!load_font(font, error)) {
        std::cerr << "carrom-client: " << error << "\n";
        return 2;
    }
    AppWindow window(options, font);
    return window.run();
}

} // namespace carrom::client::app
