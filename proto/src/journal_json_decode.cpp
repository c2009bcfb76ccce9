// Decoding of match journals (see journal_json.hpp). Never throws: every value is type- and
// range-checked before use, and the first problem is returned with its path.

#include "carrom/proto/journal_json.hpp"

#include "carrom/proto/limits.hpp"
#include "carrom/proto/match_json.hpp"
#include "carrom/proto/types.hpp"
#include "carrom/rules/seat.hpp"
#include "scene_json_read.hpp"

#include <initializer_list>
#include <limits>

namespace carrom::proto {
namespace {

using namespace scene_json_detail;

constexpr int kMaxVersion = 1000000000;
constexpr std::size_t kMaxFouls = 16;
constexpr std::size_t kMaxServerVersionBytes = 64;

// Reads required fields of one object in sequence; after the first problem it reads nothing and
// returns defaults, so callers read everything and check `error` once.
class Reader {
public:
    Reader(const Json& j, std::string path) : j_(j), path_(std::move(path)) {}

    MaybeError error;

    std::string at(std::string_view key) const { return field_path(path_, key); }

    // The field's value, or nullptr (and an error) when it is missing.
    const Json* field(std::string_view key) {
        if (error) {
            return nullptr;
        }
        if (auto e = require_field(j_, key, path_)) {
            error = e;
            return nullptr;
        }
        return &j_[std::string(key)];
    }
    // The field's value, or nullptr when it is absent or null.
    const Json* optional(std::string_view key) {
        if (error || !j_.contains(key) || j_[std::string(key)].is_null()) {
            return nullptr;
        }
        return &j_[std::string(key)];
    }
    std::int64_t int64(std::string_view key, std::int64_t lo, std::int64_t hi) {
        std::int64_t v = lo;
        if (const Json* value = field(key)) {
            error = read_integer(*value, at(key), lo, hi, v);
        }
        return error ? lo : v;
    }
    int integer(std::string_view key, int lo, int hi) {
        return static_cast<int>(int64(key, lo, hi));
    }
    bool boolean(std::string_view key) {
        bool v = false;
        if (const Json* value = field(key)) {
            error = read_bool(*value, at(key), v);
        }
        return v;
    }
    // A string accepted by valid(), which the message describes.
    std::string text(std::string_view key, std::size_t max_bytes, bool (*valid)(std::string_view),
                     std::string_view requirement) {
        std::string v;
        if (const Json* value = field(key)) {
            error = read_string(*value, at(key), max_bytes, v);
            if (!error && !valid(v)) {
                error = make_error(scene_code::kBadValue, at(key),
                                   at(key) + " must be " + std::string(requirement));
            }
        }
        return v;
    }
    std::uint64_t hash(std::string_view key) {
        std::uint64_t v = 0;
        std::string text;
        if (const Json* value = field(key)) {
            error = read_string(*value, at(key), 64, text);
            if (!error && !parse_hash_hex(text, v)) {
                error = make_error(scene_code::kBadValue, at(key),
                                   at(key) + " must be 16 lowercase hex digits");
            }
        }
        return v;
    }
    // An array of at most max_items integers in [lo, hi]; exactly max_items when exact.
    std::vector<int> ints(std::string_view key, int lo, int hi, std::size_t max_items, bool exact) {
        std::vector<int> out;
        const Json* a = field(key);
        if (a == nullptr) {
            return out;
        }
        if (!a->is_array() || a->size() > max_items || (exact && a->size() != max_items)) {
            error = make_error(scene_code::kWrongType, at(key),
                               at(key) + " must be an array of " + (exact ? "" : "at most ") +
                                   std::to_string(max_items) + " integers");
            return out;
        }
        for (std::size_t i = 0; i < a->size() && !error; ++i) {
            std::int64_t v = 0;
            error = read_integer((*a)[i], index_path(at(key), i), lo, hi, v);
            out.push_back(static_cast<int>(v));
        }
        return out;
    }

private:
    const Json& j_;
    std::string path_;
};

bool any_text(std::string_view text) {
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            return false;
        }
    }
    return true;
}

bool rule_set_name(std::string_view text) {
    rules::RuleSet unused{};
    return rules::parse_rule_set(text, unused);
}

std::vector<rules::RuleCode> read_fouls(Reader& r, std::string_view key) {
    std::vector<rules::RuleCode> out;
    const Json* a = r.field(key);
    if (a == nullptr) {
        return out;
    }
    if (!a->is_array() || a->size() > kMaxFouls) {
        r.error = make_error(scene_code::kWrongType, r.at(key),
                             r.at(key) + " must be an array of at most " +
                                 std::to_string(kMaxFouls) + " rule codes");
        return out;
    }
    for (std::size_t i = 0; i < a->size(); ++i) {
        const std::string at = index_path(r.at(key), i);
        std::string text;
        rules::RuleCode code{};
        if ((r.error = read_string((*a)[i], at, 64, text))) {
            return out;
        }
        if (!rules::parse_rule_code(text, code)) {
            r.error = make_error(scene_code::kBadValue, at, at + " is not a rule code");
            return out;
        }
        out.push_back(code);
    }
    return out;
}

MaybeError decode_outcome(const Json& j, const std::string& path, int seats, int teams,
                          OutcomeRecord& out) {
    if (auto e = check_object(
            j, path,
            {"state_hash", "pocketed", "fouls", "scores", "next_seat", "board_end", "game_end"})) {
        return e;
    }
    Reader r(j, path);
    out.state_hash = r.hash("state_hash");
    out.pocketed =
        r.ints("pocketed", 0, kCoinCount - 1, static_cast<std::size_t>(kCoinCount), false);
    out.fouls = read_fouls(r, "fouls");
    out.scores =
        r.ints("scores", -kMaxFileScore, kMaxFileScore, static_cast<std::size_t>(teams), true);
    out.next_seat = r.integer("next_seat", 0, seats - 1);
    if (const Json* board = r.optional("board_end")) {
        auto decoded = decode_board_result(*board, teams, r.at("board_end"));
        r.error = decoded.error;
        out.board_end = decoded.value;
    }
    if (const Json* game = r.optional("game_end")) {
        auto decoded = decode_game_result(*game, teams, r.at("game_end"));
        r.error = decoded.error;
        out.game_end = decoded.value;
    }
    return r.error;
}

MaybeError decode_seats(const Json& j, const std::string& path, int seat_count,
                        std::vector<JournalSeat>& out) {
    if (!j.is_array() || j.size() != static_cast<std::size_t>(seat_count)) {
        return make_error(scene_code::kWrongType, path,
                          path + " must be an array of " + std::to_string(seat_count) +
                              " seats (rules.seat_count)");
    }
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string at = index_path(path, i);
        if (auto e = check_object(j[i], at, {"name", "bot"})) {
            return e;
        }
        Reader r(j[i], at);
        JournalSeat seat;
        seat.name = r.text("name", kMaxNameBytes, &is_player_name, "a player name");
        seat.bot = r.boolean("bot");
        if (r.error) {
            return r.error;
        }
        out.push_back(std::move(seat));
    }
    return std::nullopt;
}

MaybeError decode_versions(const Json& j, const std::string& path, JournalVersions& out) {
    if (auto e = check_object(j, path, {"server", "physics", "rules"})) {
        return e;
    }
    Reader r(j, path);
    out.server =
        r.text("server", kMaxServerVersionBytes, &any_text, "text without control characters");
    out.physics = r.integer("physics", 1, kMaxVersion);
    out.rules = r.integer("rules", 1, kMaxVersion);
    return r.error;
}

// Every entry type's fields besides "type" and "time_ms".
struct EntryShape {
    std::string_view type;
    std::initializer_list<std::string_view> keys;
};

const EntryShape kShapes[] = {
    {"stroke", {"type", "time_ms", "turn", "seat", "shot", "result_hash", "outcome"}},
    {"clock_expired", {"type", "time_ms", "turn", "seat", "outcome"}},
    {"forfeit", {"type", "time_ms", "turn", "seat", "reason", "outcome"}},
    {"join", {"type", "time_ms", "seat", "name", "bot"}},
    {"leave", {"type", "time_ms", "seat"}},
    {"drop", {"type", "time_ms", "seat"}},
    {"return", {"type", "time_ms", "seat"}},
    {"rematch", {"type", "time_ms", "next_match"}},
};

MaybeError read_event(Reader& r, std::string_view type, int seats, int teams, JournalEvent& out) {
    const auto outcome = [&](OutcomeRecord& record) {
        if (const Json* o = r.field("outcome")) {
            r.error = decode_outcome(*o, r.at("outcome"), seats, teams, record);
        }
    };
    const int max_turn = static_cast<int>(kMaxTurn);
    if (type == "stroke") {
        StrokeEntry e;
        e.turn = r.integer("turn", 0, max_turn);
        e.seat = r.integer("seat", 0, seats - 1);
        if (const Json* shot = r.field("shot")) {
            auto decoded = decode_rules_shot(*shot, r.at("shot"));
            r.error = decoded.error;
            e.shot = decoded.value;
        }
        e.result_hash = r.hash("result_hash");
        outcome(e.outcome);
        out = e;
    } else if (type == "clock_expired") {
        ClockExpiredEntry e;
        e.turn = r.integer("turn", 0, max_turn);
        e.seat = r.integer("seat", 0, seats - 1);
        outcome(e.outcome);
        out = e;
    } else if (type == "forfeit") {
        ForfeitEntry e;
        e.turn = r.integer("turn", 0, max_turn);
        e.seat = r.integer("seat", 0, seats - 1);
        if (const Json* reason = r.field("reason");
            reason != nullptr &&
            !(reason->is_string() && parse(reason->get_ref<const std::string&>(), e.reason))) {
            r.error = make_error(scene_code::kBadValue, r.at("reason"),
                                 r.at("reason") + " must be \"left\" or \"grace_expired\"");
        }
        outcome(e.outcome);
        out = e;
    } else if (type == "join") {
        SeatJoinedEntry e;
        e.seat = r.integer("seat", 0, seats - 1);
        e.name = r.text("name", kMaxNameBytes, &is_player_name, "a player name");
        e.bot = r.boolean("bot");
        out = e;
    } else if (type == "rematch") {
        out = RematchEntry{r.text("next_match", kMaxMatchIdBytes, &is_match_id, "a match id")};
    } else {
        const int seat = r.integer("seat", 0, seats - 1);
        if (type == "leave") {
            out = SeatLeftEntry{seat};
        } else if (type == "drop") {
            out = SeatDroppedEntry{seat};
        } else {
            out = SeatReturnedEntry{seat};
        }
    }
    return r.error;
}

} // namespace

Decoded<MatchCreated> decode_match_created(const nlohmann::json& j, const std::string& path) {
    Decoded<MatchCreated> out;
    if ((out.error = check_object(j, path,
                                  {"match_id", "rematch_of", "room", "rule_set", "rules", "physics",
                                   "seats", "first_turn", "versions", "time_ms"}))) {
        return out;
    }
    MatchCreated& c = out.value;
    Reader r(j, path);
    c.match_id = r.text("match_id", kMaxMatchIdBytes, &is_match_id, "a match id");
    if (r.field("rematch_of") != nullptr) {
        if (const Json* previous = r.optional("rematch_of")) {
            std::string text;
            if (!(r.error = read_string(*previous, r.at("rematch_of"), kMaxMatchIdBytes, text)) &&
                !is_match_id(text)) {
                r.error = make_error(scene_code::kBadValue, r.at("rematch_of"),
                                     r.at("rematch_of") + " must be a match id or null");
            }
            c.rematch_of = text;
        }
    }
    c.room_code = r.text("room", kRoomCodeLength, &is_room_code, "a room code");
    rules::parse_rule_set(r.text("rule_set", 32, &rule_set_name, "a rule set name"), c.rule_set);
    if (const Json* rules = r.field("rules")) {
        auto decoded = decode_rules_config(*rules, {}, r.at("rules"));
        r.error = decoded.error;
        c.rules = decoded.value;
    }
    if (const Json* physics = r.field("physics")) {
        auto decoded = decode_config(*physics, {}, r.at("physics"));
        r.error = decoded.error;
        c.physics = decoded.value;
    }
    if (const Json* seats = r.field("seats")) {
        r.error = decode_seats(*seats, r.at("seats"), c.rules.seat_count, c.seats);
    }
    c.first_turn = r.integer("first_turn", 0, static_cast<int>(kMaxTurn));
    if (const Json* versions = r.field("versions")) {
        r.error = decode_versions(*versions, r.at("versions"), c.versions);
    }
    c.time_ms = r.int64("time_ms", 0, kMaxTimeMs);
    out.error = r.error;
    return out;
}

Decoded<JournalEntry> decode_journal_entry(const nlohmann::json& j, const MatchCreated& created,
                                           const std::string& path) {
    Decoded<JournalEntry> out;
    std::string type;
    if ((out.error = require_field(j, "type", path)) ||
        (out.error = read_string(j["type"], field_path(path, "type"), 32, type))) {
        return out;
    }
    const EntryShape* shape = nullptr;
    for (const EntryShape& s : kShapes) {
        shape = s.type == type ? &s : shape;
    }
    if (shape == nullptr) {
        out.error = make_error(scene_code::kBadValue, field_path(path, "type"),
                               field_path(path, "type") + " names no journal entry");
        return out;
    }
    if ((out.error = check_object(j, path, shape->keys))) {
        return out;
    }
    Reader r(j, path);
    out.value.time_ms = r.int64("time_ms", 0, kMaxTimeMs);
    const int seats = created.rules.seat_count;
    if (!r.error) {
        r.error = read_event(r, type, seats, rules::team_count(seats), out.value.event);
    }
    out.error = r.error;
    return out;
}

Decoded<MatchJournal> decode_journal(const nlohmann::json& j) {
    Decoded<MatchJournal> out;
    if ((out.error = check_object(j, "", {"format", "match", "entries"}))) {
        return out;
    }
    Reader r(j, "");
    const auto format = r.int64("format", 1, std::numeric_limits<int>::max());
    if (!r.error && format > kJournalFormat) {
        out.error = make_error(journal_code::kUnsupportedFormat, "format",
                               "the journal has format " + std::to_string(format) +
                                   "; this build reads format " + std::to_string(kJournalFormat) +
                                   " and older");
        return out;
    }
    if (const Json* match = r.field("match")) {
        auto decoded = decode_match_created(*match, "match");
        r.error = decoded.error;
        out.value.created = std::move(decoded.value);
    }
    const Json* entries = r.field("entries");
    if (r.error || entries == nullptr) {
        out.error = r.error;
        return out;
    }
    if (!entries->is_array() || entries->size() > kMaxJournalEntries) {
        out.error = make_error(scene_code::kWrongType, "entries",
                               "entries must be an array of at most " +
                                   std::to_string(kMaxJournalEntries) + " entries");
        return out;
    }
    out.value.entries.reserve(entries->size());
    for (std::size_t i = 0; i < entries->size(); ++i) {
        auto entry =
            decode_journal_entry((*entries)[i], out.value.created, index_path("entries", i));
        if (!entry.ok()) {
            out.error = entry.error;
            return out;
        }
        out.value.entries.push_back(std::move(entry.value));
    }
    return out;
}

Decoded<MatchJournal> decode_journal_text(std::string_view text) {
    auto parsed = parse_json_text(text, kMaxJournalBytes);
    if (!parsed.ok()) {
        Decoded<MatchJournal> out;
        out.error = parsed.error;
        return out;
    }
    return decode_journal(parsed.value);
}

} // namespace carrom::proto
