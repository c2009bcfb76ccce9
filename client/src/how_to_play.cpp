#include "carrom/client/how_to_play.hpp"

#include "carrom/client/plain_words.hpp"

namespace carrom::client {

HowToPlay how_to_play(proto::RuleSet rule_set) {
    HowToPlay h;
    h.title = rule_set_name(rule_set);
    switch (rule_set) {
    case proto::RuleSet::Icf:
        h.foul = "Foul: the striker in a pocket costs a due: one of your pocketed coins comes back "
                 "to the centre (owed if you have none yet) and the turn passes, unless your own "
                 "coins went in with it (they come back too).";
        h.rules = {
            "Pocket your own colour with the striker; the breaker plays white.",
            "Your own coin or the queen in a pocket: you shoot again. Otherwise the turn passes.",
            "The queen (red) counts only after one of your coins, and only when you cover it: "
            "pocket an own coin in the same or the next stroke, or it comes back.",
            h.foul,
            "Clear your coins after the queen is covered to win the board: 1 point for each "
            "opponent coin left, plus 3 for the queen (at most 12 a board).",
            "Your last coin before the queen is covered, or the opponent's last coin, loses the "
            "board.",
            "Points come at the end of a board. 25 points, or the lead after 8 boards, win the "
            "game.",
        };
        break;
    case proto::RuleSet::Seed:
        h.foul = "Foul: the striker in a pocket returns your most recently pocketed coin (and its "
                 "point) and the turn passes.";
        h.rules = {
            "The bottom seat plays black, the top seat white.",
            "Every coin scores 1 for its colour, whoever pockets it; your own coin lets you shoot "
            "again.",
            "The queen may go in at any time; cover it with your own coin in the same or the next "
            "stroke for 3 points, or it comes back.",
            h.foul,
            "When a colour is cleared the game ends: the higher score wins.",
        };
        break;
    case proto::RuleSet::Freestyle:
        h.foul = "Foul: the striker in a pocket costs 20 points and the turn (a score may go below "
                 "zero).";
        h.rules = {
            "Anyone may pocket any coin: white scores 20, black 10.",
            "Any coin or the queen in a pocket: you shoot again.",
            "The queen scores 50 once covered by any coin in the same or the next stroke, or it "
            "comes back.",
            h.foul,
            "The first to the room's target points wins; when the coins run out, the higher score "
            "wins.",
        };
        break;
    case proto::RuleSet::DiscPool:
        h.foul = "Foul: the striker in a pocket returns the stroke's own coins plus a due, and the "
                 "turn passes.";
        h.rules = {
            "No queen. Each side owns the nine coins of its colour; the breaker plays white.",
            "Your own coin keeps the turn; an opponent's coin stays down and passes it.",
            h.foul,
            "Clear your coins first to win; pocketing the opponent's last coin makes them win.",
        };
        break;
    }
    return h;
}

std::vector<std::string> controls_help() {
    return {
        "Place: drag the striker along your baseline (or the arrow keys). It may not overlap a "
        "coin.",
        "Aim and power: press on the striker and pull back; the line shows where it goes, the "
        "ring how hard. Release to shoot.",
        "Cancel a pull: Escape, the right button, a second finger or Cancel shot.",
        "Shot clock: when it runs out the turn passes; three missed turns in a row lose the game.",
    };
}

std::vector<std::string> walkthrough_steps(proto::RuleSet rule_set) {
    return {
        "1/4 Place: drag the striker sideways along your baseline. Over a coin it turns red and "
        "cannot shoot.",
        "2/4 Aim: press on the striker and pull back, away from where it should go. The dotted "
        "line shows the way.",
        "3/4 Power: the farther you pull, the harder the shot; the ring fills. Release to shoot, "
        "Escape cancels.",
        "4/4 " + how_to_play(rule_set).foul,
    };
}

} // namespace carrom::client
