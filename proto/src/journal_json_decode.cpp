// Decoding of match journals (see journal_json.hpp), read with JsonReader in the Document wording.
// Never throws: every value is type- and range-checked before use, and the first problem is
// returned with its path.

#include "carrom/proto/journal_json.hpp"

#include "carrom/proto/limits.hpp"
#include "carrom/proto/match_json.hpp"
#include "carrom/proto/types.hpp"
#include "carrom/rules/seat.hpp"
#include "json_reader.hpp"

#include <initializer_list>
#include <limits>

namespace carrom::proto {
namespace {

constexpr int kMaxVersion = 1000000000;
constexpr std::size_t kMaxFouls = 16;
constexpr std::size_t kMaxServerVersionBytes = 64;

using Json = nlohmann::json;
using MaybeError = std::optional<Error>;
using namespace detail; // JsonReader, Wording, Range, field_path, index_path

// A string of at most max_bytes that valid() accepts; otherwise "<path> must be <what>".
std::string checked_text(JsonReader& r, std::string_view key, std::size_t max_bytes,
                         bool (*valid)(std::string_view), std::string_view what) {
    std::string text = r.text(key, 0, max_bytes);
    if (r.ok() && !valid(text)) {
        r.fail(key, "must be " + std::string(what));
    }
    return text;
}

bool is_hash(std::string_view text) {
    std::uint64_t unused = 0;
    return parse_hash_hex(text, unused);
}

std::uint64_t read_hash(JsonReader& r, std::string_view key) {
    std::uint64_t out = 0;
    parse_hash_hex(checked_text(r, key, 64, &is_hash, "16 lowercase hex digits"), out);
    return out;
}

bool any_text(std::string_view text) {
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            return false;
        }
    }
    return true;
}

std::vector<rules::RuleCode> read_fouls(JsonReader& r, std::string_view key) {
    std::vector<rules::RuleCode> out;
    const Json* a = r.find(key);
    if (a != nullptr && (!a->is_array() || a->size() > kMaxFouls)) {
        r.fail(key, "must be an array of at most " + std::to_string(kMaxFouls) + " rule codes",
               scene_code::kWrongType);
    }
    for (std::size_t i = 0; r.ok() && i < a->size(); ++i) {
        out.push_back(r.enumeration_at((*a)[i], index_path(r.path_of(key), i),
                                       rules::kRuleCodeNames, rules::RuleCode{},
                                       "is not a rule code"));
    }
    return out;
}

MaybeError decode_outcome(const Json& j, const std::string& path, int seats, int teams,
                          OutcomeRecord& out) {
    JsonReader r(j, path, Wording::Document);
    r.only_keys(
        {"state_hash", "pocketed", "fouls", "scores", "next_seat", "board_end", "game_end"});
    out.state_hash = read_hash(r, "state_hash");
    out.pocketed = r.int_array("pocketed", 0, kCoinCount - 1, static_cast<std::size_t>(kCoinCount));
    out.fouls = read_fouls(r, "fouls");
    out.scores =
        r.int_array("scores", -kMaxFileScore, kMaxFileScore, static_cast<std::size_t>(teams), true);
    out.next_seat = r.small_int("next_seat", 0, seats - 1);
    if (const Json* board = r.find_optional("board_end")) {
        auto decoded = decode_board_result(*board, teams, r.path_of("board_end"));
        r.merge(decoded.error);
        out.board_end = decoded.value;
    }
    if (const Json* game = r.find_optional("game_end")) {
        auto decoded = decode_game_result(*game, teams, r.path_of("game_end"));
        r.merge(decoded.error);
        out.game_end = decoded.value;
    }
    return r.error();
}

MaybeError decode_seats(const Json& j, const std::string& path, int seat_count,
                        std::vector<JournalSeat>& out) {
    if (!j.is_array() || j.size() != static_cast<std::size_t>(seat_count)) {
        return Error{std::string(scene_code::kWrongType),
                     path + " must be an array of " + std::to_string(seat_count) +
                         " seats (rules.seat_count)",
                     path};
    }
    for (std::size_t i = 0; i < j.size(); ++i) {
        JsonReader r(j[i], index_path(path, i), Wording::Document);
        r.only_keys({"name", "bot"});
        JournalSeat seat;
        seat.name = checked_text(r, "name", kMaxNameBytes, &is_player_name, "a player name");
        seat.bot = r.boolean("bot");
        if (!r.ok()) {
            return r.error();
        }
        out.push_back(std::move(seat));
    }
    return std::nullopt;
}

MaybeError decode_versions(const Json& j, const std::string& path, JournalVersions& out) {
    JsonReader r(j, path, Wording::Document);
    r.only_keys({"server", "physics", "rules"});
    out.server = checked_text(r, "server", kMaxServerVersionBytes, &any_text,
                              "text without control characters");
    out.physics = r.small_int("physics", 1, kMaxVersion);
    out.rules = r.small_int("rules", 1, kMaxVersion);
    return r.error();
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

MaybeError read_event(JsonReader& r, std::string_view type, int seats, int teams,
                      JournalEvent& out) {
    const auto outcome = [&](OutcomeRecord& record) {
        if (const Json* o = r.find("outcome")) {
            r.merge(decode_outcome(*o, r.path_of("outcome"), seats, teams, record));
        }
    };
    const int max_turn = static_cast<int>(kMaxTurn);
    if (type == "stroke") {
        StrokeEntry e;
        e.turn = r.small_int("turn", 0, max_turn);
        e.seat = r.small_int("seat", 0, seats - 1);
        if (const Json* shot = r.find("shot")) {
            auto decoded = decode_rules_shot(*shot, r.path_of("shot"));
            r.merge(decoded.error);
            e.shot = decoded.value;
        }
        e.result_hash = read_hash(r, "result_hash");
        outcome(e.outcome);
        out = e;
    } else if (type == "clock_expired") {
        ClockExpiredEntry e;
        e.turn = r.small_int("turn", 0, max_turn);
        e.seat = r.small_int("seat", 0, seats - 1);
        outcome(e.outcome);
        out = e;
    } else if (type == "forfeit") {
        ForfeitEntry e;
        e.turn = r.small_int("turn", 0, max_turn);
        e.seat = r.small_int("seat", 0, seats - 1);
        e.reason = r.enumeration("reason", kForfeitReasonNames, e.reason);
        outcome(e.outcome);
        out = e;
    } else if (type == "join") {
        SeatJoinedEntry e;
        e.seat = r.small_int("seat", 0, seats - 1);
        e.name = checked_text(r, "name", kMaxNameBytes, &is_player_name, "a player name");
        e.bot = r.boolean("bot");
        out = e;
    } else if (type == "rematch") {
        out = RematchEntry{
            checked_text(r, "next_match", kMaxMatchIdBytes, &is_match_id, "a match id")};
    } else {
        const int seat = r.small_int("seat", 0, seats - 1);
        if (type == "leave") {
            out = SeatLeftEntry{seat};
        } else if (type == "drop") {
            out = SeatDroppedEntry{seat};
        } else {
            out = SeatReturnedEntry{seat};
        }
    }
    return r.error();
}

} // namespace

Decoded<MatchCreated> decode_match_created(const nlohmann::json& j, const std::string& path) {
    MatchCreated c;
    JsonReader r(j, path, Wording::Document);
    r.only_keys({"match_id", "rematch_of", "room", "rule_set", "rules", "physics", "seats",
                 "first_turn", "versions", "time_ms"});
    c.match_id = checked_text(r, "match_id", kMaxMatchIdBytes, &is_match_id, "a match id");
    if (r.find("rematch_of") != nullptr && r.find_optional("rematch_of") != nullptr) {
        c.rematch_of = r.text("rematch_of", 0, kMaxMatchIdBytes);
        if (r.ok() && !is_match_id(c.rematch_of)) {
            r.fail("rematch_of", "must be a match id or null");
        }
    }
    c.room_code = checked_text(r, "room", kRoomCodeLength, &is_room_code, "a room code");
    c.rule_set = r.enumeration("rule_set", rules::kRuleSetNames, c.rule_set);
    if (const Json* rules = r.find("rules")) {
        auto decoded = decode_rules_config(*rules, {}, r.path_of("rules"));
        r.merge(decoded.error);
        c.rules = decoded.value;
    }
    if (const Json* physics = r.find("physics")) {
        auto decoded = decode_config(*physics, {}, r.path_of("physics"));
        r.merge(decoded.error);
        c.physics = decoded.value;
    }
    if (const Json* seats = r.find("seats")) {
        r.merge(decode_seats(*seats, r.path_of("seats"), c.rules.seat_count, c.seats));
    }
    c.first_turn = r.small_int("first_turn", 0, static_cast<int>(kMaxTurn));
    if (const Json* versions = r.find("versions")) {
        r.merge(decode_versions(*versions, r.path_of("versions"), c.versions));
    }
    c.time_ms = r.integer("time_ms", 0, kMaxTimeMs);
    return {std::move(c), r.error()};
}

Decoded<JournalEntry> decode_journal_entry(const nlohmann::json& j, const MatchCreated& created,
                                           const std::string& path) {
    JournalEntry out;
    JsonReader r(j, path, Wording::Document);
    const std::string type = r.text("type", 0, 32);
    const EntryShape* shape = nullptr;
    for (const EntryShape& s : kShapes) {
        shape = s.type == type ? &s : shape;
    }
    if (r.ok() && shape == nullptr) {
        r.fail("type", "names no journal entry");
    }
    if (r.ok() && r.only_keys(shape->keys)) {
        out.time_ms = r.integer("time_ms", 0, kMaxTimeMs);
        const int seats = created.rules.seat_count;
        if (r.ok()) {
            r.merge(read_event(r, type, seats, rules::team_count(seats), out.event));
        }
    }
    return {std::move(out), r.error()};
}

Decoded<MatchJournal> decode_journal(const nlohmann::json& j) {
    Decoded<MatchJournal> out;
    JsonReader r(j, "", Wording::Document);
    r.only_keys({"format", "match", "entries"});
    const auto format = r.integer("format", 1, std::numeric_limits<int>::max());
    if (r.ok() && format > kJournalFormat) {
        out.error =
            Error{std::string(journal_code::kUnsupportedFormat),
                  "the journal has format " + std::to_string(format) +
                      "; this build reads format " + std::to_string(kJournalFormat) + " and older",
                  "format"};
        return out;
    }
    if (const Json* match = r.find("match")) {
        auto decoded = decode_match_created(*match, "match");
        r.merge(decoded.error);
        out.value.created = std::move(decoded.value);
    }
    const Json* entries = r.find("entries");
    if (entries != nullptr && (!entries->is_array() || entries->size() > kMaxJournalEntries)) {
        r.fail("entries",
               "must be an array of at most " + std::to_string(kMaxJournalEntries) + " entries",
               scene_code::kWrongType);
    }
    for (std::size_t i = 0; r.ok() && i < entries->size(); ++i) {
        auto entry =
            decode_journal_entry((*entries)[i], out.value.created, index_path("entries", i));
        r.merge(entry.error);
        out.value.entries.push_back(std::move(entry.value));
    }
    out.error = r.error();
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
