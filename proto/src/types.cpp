#include "carrom/proto/types.hpp"

#include "carrom/proto/limits.hpp"

#include <cstring>

namespace carrom::proto {

using enum_names::name_or_unknown;
using enum_names::parse_into;

std::string_view to_string(RuleSet value) {
    return name_or_unknown(kRuleSetNames, value);
}
std::string_view to_string(Role value) {
    return name_or_unknown(kRoleNames, value);
}
std::string_view to_string(Colour value) {
    return name_or_unknown(kColourNames, value);
}
std::string_view to_string(Phase value) {
    return name_or_unknown(kPhaseNames, value);
}
std::string_view to_string(QueenState value) {
    return name_or_unknown(kQueenStateNames, value);
}
std::string_view to_string(BotLevel value) {
    return name_or_unknown(kBotLevelNames, value);
}
std::string_view to_string(Emote value) {
    return name_or_unknown(kEmoteNames, value);
}
std::string_view baseline_name(Baseline value) {
    return name_or_unknown(rules::kSideNames, value);
}
std::string_view body_kind_name(BodyKind value) {
    return name_or_unknown(kBodyKindNames, value);
}

bool parse(std::string_view text, RuleSet& out) {
    return parse_into(kRuleSetNames, text, out);
}
bool parse(std::string_view text, Role& out) {
    return parse_into(kRoleNames, text, out);
}
bool parse(std::string_view text, Colour& out) {
    return parse_into(kColourNames, text, out);
}
bool parse(std::string_view text, Phase& out) {
    return parse_into(kPhaseNames, text, out);
}
bool parse(std::string_view text, QueenState& out) {
    return parse_into(kQueenStateNames, text, out);
}
bool parse(std::string_view text, BotLevel& out) {
    return parse_into(kBotLevelNames, text, out);
}
bool parse(std::string_view text, Emote& out) {
    return parse_into(kEmoteNames, text, out);
}
bool parse(std::string_view text, Baseline& out) {
    return parse_into(rules::kSideNames, text, out);
}
bool parse(std::string_view text, BodyKind& out) {
    return parse_into(kBodyKindNames, text, out);
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

namespace {
bool is_lowercase_hex(std::string_view text, std::size_t length) {
    if (text.size() != length) {
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
} // namespace

bool is_resume_token(std::string_view text) {
    return is_lowercase_hex(text, kResumeTokenLength);
}

bool is_identity_key(std::string_view text) {
    return is_lowercase_hex(text, kIdentityKeyLength);
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
