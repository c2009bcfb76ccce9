#pragma once
// The page the lobby's leaderboard and "My matches" views share: a title, a line under it (what
// the list is, or the sentence why it is not there), a row of buttons, a header and up to 20
// rows in columns. Drawn in the lobby's area with the lobby's colours.

#include "carrom/client/screen_mapping.hpp"
#include "text.hpp"

#include <SFML/Graphics.hpp>

#include <string>
#include <vector>

namespace carrom::client::app {

struct ListColumn {
    std::string header;
    double x = 0.0; // its anchor, as a fraction of the page's width
    Align align = Align::Left;
};

struct ListPage {
    std::string title;
    std::string note; // under the title: what is shown, or why nothing is
    bool note_is_error = false;
    std::vector<std::string> buttons; // left to right
    std::vector<ListColumn> columns;
    std::vector<std::vector<std::string>> rows; // each with one text per column
    bool rows_are_buttons = false;              // rows drawn as buttons (they open something)
};

inline constexpr int kListPageRows = 20;

// Button i of count in area's button row.
Rect list_button_rect(const Rect& area, int i, int count);
// Row i (0 to kListPageRows - 1) in area.
Rect list_row_rect(const Rect& area, int i);
void draw_list_page(sf::RenderTarget& target, const sf::Font& font, const Rect& area,
                    const ListPage& page);

} // namespace carrom::client::app
