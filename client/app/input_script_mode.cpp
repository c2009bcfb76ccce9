#include "input_script_mode.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <iostream>
#include <string_view>
#include <utility>

namespace carrom::client::app {
namespace {

std::optional<sf::Keyboard::Key> key_named(const std::string& name) {
    if (name.size() == 1 && std::islower(static_cast<unsigned char>(name[0]))) {
        return static_cast<sf::Keyboard::Key>(sf::Keyboard::A + (name[0] - 'a'));
    }
    static constexpr std::pair<std::string_view, sf::Keyboard::Key> kNamedKeys[] = {
        {"Escape", sf::Keyboard::Escape}, {"Enter", sf::Keyboard::Enter},
        {"F1", sf::Keyboard::F1},         {"F2", sf::Keyboard::F2},
        {"F3", sf::Keyboard::F3},         {"Tab", sf::Keyboard::Tab}};
    for (const auto& [named, key] : kNamedKeys) {
        if (name == named) {
            return key;
        }
    }
    return std::nullopt;
}

} // namespace

void InputScriptMode::on_frame(UnattendedFrame& frame) {
    frame.input_pending = next_ < tokens_.size();
    if (!frame.input_pending) {
        return;
    }
    const nlohmann::json ui = nlohmann::json::parse(frame.ui, nullptr, false);
    if (started_at_ < 0) {
        const MatchView& v = frame.model.view();
        const bool ready = in_lobby_
                               ? ui.is_object() && ui.value("session", "") == "lobby"
                               : v.in_room && frame.model.my_turn() && !frame.model.animating();
        if (!ready) {
            return;
        }
        started_at_ = frame.number;
    }
    if ((frame.number - started_at_) % kFramesApart != 0) {
        return;
    }
    const std::string& token = tokens_[next_++];
    if (token == "wait") {
        return;
    }
    if (const auto key = key_named(token)) {
        sf::Event e{};
        e.type = sf::Event::KeyPressed;
        e.key.code = *key;
        frame.input.push_back(e);
        if (token.size() == 1) {
            sf::Event text{};
            text.type = sf::Event::TextEntered;
            text.text.unicode = static_cast<sf::Uint32>(token[0]);
            frame.input.push_back(text);
        }
        return;
    }
    const std::size_t colon = token.find(':');
    const std::string list = token.substr(0, colon) + "_buttons";
    const int index = colon == std::string::npos ? -1 : std::atoi(token.c_str() + colon + 1);
    if (!ui.is_object() || !ui.contains(list) || index < 0 ||
        static_cast<std::size_t>(index) >= ui.at(list).size()) {
        std::cerr << "carrom-client: --input " << token << ": no such button shown\n";
        return;
    }
    const nlohmann::json& r = ui.at(list).at(static_cast<std::size_t>(index));
    for (const sf::Event::EventType type :
         {sf::Event::MouseButtonPressed, sf::Event::MouseButtonReleased}) {
        sf::Event e{};
        e.type = type;
        e.mouseButton.button = sf::Mouse::Left;
        e.mouseButton.x =
            static_cast<int>(std::lround(r.at("x").get<double>() + r.at("w").get<double>() / 2.0));
        e.mouseButton.y =
            static_cast<int>(std::lround(r.at("y").get<double>() + r.at("h").get<double>() / 2.0));
        frame.input.push_back(e);
    }
}

} // namespace carrom::client::app
