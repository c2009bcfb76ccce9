#include "window_output.hpp"

#include <SFML/Graphics/Texture.hpp>

#include <fstream>
#include <iostream>

namespace carrom::client::app {

bool handle_window_event(sf::RenderWindow& window, const sf::Event& e, ScreenLayout& layout,
                         int seats) {
    if (e.type == sf::Event::Closed) {
        window.close();
        return true;
    }
    if (e.type == sf::Event::Resized) {
        const float w = static_cast<float>(e.size.width);
        const float h = static_cast<float>(e.size.height);
        window.setView(sf::View(sf::FloatRect(0.0f, 0.0f, w, h)));
        layout = make_layout(w, h, seats, true);
        return true;
    }
    return false;
}

bool save_window_png(const sf::RenderWindow& window, const std::string& path) {
    sf::Texture shot;
    const sf::Vector2u size = window.getSize();
    if (!shot.create(size.x, size.y)) {
        return false;
    }
    shot.update(window);
    return shot.copyToImage().saveToFile(path);
}

int write_final_state_file(const std::string& path, const std::string& json) {
    std::ofstream out(path);
    out << json << "\n";
    if (!out) {
        std::cerr << "carrom-client: could not write " << path << "\n";
        return 1;
    }
    std::cout << "final state " << path << std::endl;
    return 0;
}

} // namespace carrom::client::app
