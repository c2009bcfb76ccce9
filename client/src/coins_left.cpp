#include "carrom/client/coins_left.hpp"

namespace carrom::client {

CoinsOnBoard count_coins(const std::vector<RenderedBody>& drawn) {
    CoinsOnBoard out;
    for (const RenderedBody& b : drawn) {
        if (b.falling) {
            continue;
        }
        switch (b.kind) {
        case BodyKind::White:
            ++out.white;
            break;
        case BodyKind::Black:
            ++out.black;
            break;
        case BodyKind::Queen:
            out.queen = true;
            break;
        case BodyKind::Striker:
            break;
        }
    }
    return out;
}

std::optional<SeatCoins> seat_coins(const CoinsOnBoard& board, proto::RuleSet rule_set,
                                    proto::Colour seat_colour) {
    const bool has_queen = rule_set != proto::RuleSet::DiscPool;
    const bool queen = has_queen && board.queen;
    if (rule_set == proto::RuleSet::Freestyle) {
        return SeatCoins{proto::Colour::None, board.white + board.black, queen};
    }
    switch (seat_colour) {
    case proto::Colour::White:
        return SeatCoins{seat_colour, board.white, queen};
    case proto::Colour::Black:
        return SeatCoins{seat_colour, board.black, queen};
    case proto::Colour::None:
        break;
    }
    return std::nullopt;
}

} // namespace carrom::client
