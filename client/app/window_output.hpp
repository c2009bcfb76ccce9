#pragma once
// What both windows (the match window and --replay) do alike: the window events every window
// handles the same way, and what their unattended modes write: the window as a PNG
// (--screenshot) and the final state as JSON (--final-state).

#include "carrom/client/screen_mapping.hpp"

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Window/Event.hpp>

#include <string>

namespace carrom::client::app {

// Closed closes the window; Resized gives it a view of its new size and lays the board out again
// for `seats` seats. True when e was one of them (nothing else to do with it).
bool handle_window_event(sf::RenderWindow& window, const sf::Event& e, ScreenLayout& layout,
                         int seats);

// The window's current contents saved as a PNG; false when it could not be saved.
bool save_window_png(const sf::RenderWindow& window, const std::string& path);

// Writes json and a newline to path; prints "final state PATH" on stdout and returns 0, or a
// sentence on stderr and returns 1 (the process exit code).
int write_final_state_file(const std::string& path, const std::string& json);

} // namespace carrom::client::app
