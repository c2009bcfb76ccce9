#include "carrom/rules/seat.hpp"

#include <array>

namespace carrom::rules {

std::string_view to_string(Side side) {
    return enum_names::name_or_unknown(kSideNames, side);
}

bool parse_side(std::string_view text, Side& out) {
    return enum_names::parse_into(kSideNames, text, out);
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
