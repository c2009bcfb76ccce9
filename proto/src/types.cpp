#include "carrom/proto/types.hpp"

#include "carrom/proto/limits.hpp"

#include <array>
#include <cstring>
#include <utility>

namespace carrom::proto {

namespace {

template <class E, std::size_t N> using NameTable = std::array<std::pair<E, std::string_view>, N>;

template <class E, std::size_t N> std::string_view name_of(const NameTable<E, N>& table, E value) {
    for (const auto& [e, name] : table) {
        if (e == value) {
            return name;
        }
    }
    return "unknown";
}

template <class E, std::size_t N>
bool parse_name(const NameTable<E, N>& table, std::string_view text, E& out) {
    for (const auto& [e, name] : table) {
        if (name == text) {
            out = e;
            return true;
        }
    }
    return false;
}

constexpr NameTable<RuleSet, 4> kRuleSets{{{RuleSet::Icf, "icf"},
                                           {RuleSet::Seed, "seed"},
                                           {RuleSet::Freestyle, "freestyle"},
                                           {RuleSet::DiscPool, "discpool"}}};
constexpr NameTable<Role, 2> kRoles{{{Role::Player, "player"}, {Role::Spectator, "spectator"}}};
constexpr NameTable<Colour, 3> kColours{
    {{Colour::None, "none"}, {Colour::Black, "black"}, {Colour::White, "white"}}};
constexpr NameTable<Phase, 5> kPhases{{{Phase::Waiting, "waiting"},
                                       {Phase::Aiming, "aiming"},
                                       {Phase::Moving, "moving"},
                                       {Phase::BoardOver, "board_over"},
                                       {Phase::GameOver, "game_over"}}};
constexpr NameTable<QueenState, 4> kQueenStates{{{QueenState::OnBoard, "on_board"},
                                                 {QueenState::Pending, "pending"},
                                                 {QueenState::Covered, "covered"},
                                                 {QueenState::None, "none"}}};
constexpr NameTable<BotLevel, 4> kBotLevels{{{BotLevel::Random, "random"},
                                             {BotLevel::Easy, "easy"},
                                             {BotLevel::Medium, "medium"},
                                             {BotLevel::Hard, "hard"}}};
constexpr NameTable<Baseline, 4> kBaselines{{{Baseline::Bottom, "bottom"},
                                             {Baseline::Right, "right"},
                                             {Baseline::Top, "top"},
                                             {Baseline::Left, "left"}}};

} // namespace

std::string_view to_string(RuleSet value) {
    return name_of(kRuleSets, value);
}
std::string_view to_string(Role value) {
    return name_of(kRoles, value);
}
std::string_view to_string(Colour value) {
    return name_of(kColours, value);
}
std::string_view to_string(Phase value) {
    return name_of(kPhases, value);
}
std::string_view to_string(QueenState value) {
    return name_of(kQueenStates, value);
}
std::string_view to_string(BotLevel value) {
    return name_of(kBotLevels, value);
}
std::string_view baseline_name(Baseline value) {
    return name_of(kBaselines, value);
}
std::string_view body_kind_name(BodyKind value) {
    return carrom::to_string(value); // the names live with BodyKind in common/
}

bool parse(std::string_view text, RuleSet& out) {
    return parse_name(kRuleSets, text, out);
}
bool parse(std::string_view text, Role& out) {
    return parse_name(kRoles, text, out);
}
bool parse(std::string_view text, Colour& out) {
    return parse_name(kColours, text, out);
}
bool parse(std::string_view text, Phase& out) {
    return parse_name(kPhases, text, out);
}
bool parse(std::string_view text, QueenState& out) {
    return parse_name(kQueenStates, text, out);
}
bool parse(std::string_view text, BotLevel& out) {
    return parse_name(kBotLevels, text, out);
}
bool parse(std::string_view text, Baseline& out) {
    return parse_name(kBaselines, text, out);
}
bool parse(std::string_view text, BodyKind& out) {
    return parse_body_kind(text, out);
}

bool is_room_code(std::string_view text) {
    if (text.size() != kRoomCodeLength) {
        return false;
    }
    for (char c : text) {
        if (c == '\0' || std::strchr(kRoomCodeAlphabet, c) == nullptr) {
            return false;
        }
    }
    return true;
}

bool is_resume_token(std::string_view text) {
    if (text.size() != kResumeTokenLength) {
        return false;
    }
    for (char c : text) {
        const bool hex = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
        if (!hex) {
            return false;
        }
    }
    return true;
}

bool is_player_name(std::string_view text) {
    if (text.empty() || text.size() > kMaxNameBytes) {
        return false;
    }
    bool visible = false;
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            return false;
        }
        visible = visible || byte != ' ';
    }
    return visible;
}

BoardBody to_board_body(const Body& body) {
    return {body.id, body.kind, body.pos_px, body.vel_px_s, body.pocketed};
}

Body to_body(const BoardBody& body) {
    Body out;
    out.id = body.id;
    out.kind = body.kind;
    out.pos_px = body.pos_px;
    out.vel_px_s = body.vel_px_s;
    out.pocketed = body.pocketed;
    return out;
}

rules::RuleSet to_rules(RuleSet rule_set) {
    switch (rule_set) {
    case RuleSet::Icf:
        return rules::RuleSet::Icf;
    case RuleSet::Seed:
        return rules::RuleSet::Seed;
    case RuleSet::Freestyle:
        return rules::RuleSet::Freestyle;
    case RuleSet::DiscPool:
        return rules::RuleSet::DiscPool;
    }
    return rules::RuleSet::Icf;
}

} // namespace carrom::proto
