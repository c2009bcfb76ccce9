#include "carrom/rules/seat.hpp"

#include <array>
#include <utility>

namespace carrom::rules {
namespace {

constexpr std::array<std::pair<Side, std::string_view>, 4> kSideNames{{
    {Side::Bottom, "bottom"},
    {Side::Right, "right"},
    {Side::Top, "top"},
    {Side::Left, "left"},
}};

} // namespace

std::string_view to_string(Side side) {
    for (const auto& [value, name] : kSideNames) {
        if (value == side) {
            return name;
        }
    }
    return "unknown";
}

bool parse_side(std::string_view text, Side& out) {
    for (const auto& [value, name] : kSideNames) {
        if (name == text) {
            out = value;
            return true;
        }
    }
    return false;
}

int team_of_seat(int seat, int seat_count) {
    return seat_count == 4 ? seat % 2 : seat;
}

int team_count(int seat_count) {
    return seat_count == 4 ? 2 : seat_count;
}

int next_seat(int seat, int seat_count) {
    return (seat + 1) % seat_count;
}

std::vector<Seat> make_seats(int seat_count) {
    std::vector<Seat> seats;
    if (seat_count == 4) {
        const std::array<Side, 4> sides{Side::Bottom, Side::Right, Side::Top, Side::Left};
        for (int i = 0; i < 4; ++i) {
            seats.push_back(Seat{i, sides[static_cast<std::size_t>(i)], i % 2, (i + 2) % 4});
        }
        return seats;
    }
    seats.push_back(Seat{0, Side::Bottom, 0, -1});
    seats.push_back(Seat{1, Side::Top, 1, -1});
    return seats;
}

} // namespace carrom::rules
