// Journal JSON: the exact form of every entry type and of the head, exact round trips (doubles to
// the bit), and one case per decoding error with its code and path.

#include "journal_support.hpp"

#include "carrom/proto/journal_json.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <string>

namespace carrom::proto {
namespace {

using Json = nlohmann::json;

OutcomeRecord sample_outcome() {
    OutcomeRecord o;
    o.state_hash = 0xfedcba9876543210ULL;
    o.pocketed = {4, 7};
    o.fouls = {rules::RuleCode::StrikerPocketed};
    o.scores = {3, -20};
    o.next_seat = 0;
    o.board_end = rules::BoardResult{1, 0, 3, rules::RuleCode::BoardCleared};
    return o;
}

const MatchCreated& created() {
    static const MatchCreated c = test::make_created(rules::RuleSet::Icf);
    return c;
}

Json entry_json(const JournalEvent& event, std::int64_t time_ms = 1000) {
    return journal_entry_to_json(JournalEntry{time_ms, event});
}

// Decodes one entry given as JSON text.
Decoded<JournalEntry> decode_entry(std::string_view text) {
    return decode_journal_entry(Json::parse(text), created(), "entries[0]");
}

void expect_round_trip(const JournalEvent& event) {
    const JournalEntry entry{1234, event};
    const auto decoded = decode_journal_entry(journal_entry_to_json(entry), created(), "e");
    ASSERT_TRUE(decoded.ok()) << decoded.error->path << ": " << decoded.error->message;
    EXPECT_EQ(decoded.value, entry);
}

void expect_error(const Decoded<JournalEntry>& d, std::string_view code, std::string_view path) {
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error->code, code) << d.error->message;
    EXPECT_EQ(d.error->path, path) << d.error->message;
}

TEST(JournalJson, HashesAreSixteenLowercaseHexDigits) {
    EXPECT_EQ(hash_to_hex(0), "0000000000000000");
    EXPECT_EQ(hash_to_hex(0x0123456789abcdefULL), "0123456789abcdef");
    EXPECT_EQ(hash_to_hex(~0ULL), "ffffffffffffffff");
    std::uint64_t v = 0;
    ASSERT_TRUE(parse_hash_hex("0123456789abcdef", v));
    EXPECT_EQ(v, 0x0123456789abcdefULL);
    EXPECT_FALSE(parse_hash_hex("0123456789ABCDEF", v));
    EXPECT_FALSE(parse_hash_hex("0123456789abcde", v));
    EXPECT_FALSE(parse_hash_hex("0123456789abcdef0", v));
    EXPECT_FALSE(parse_hash_hex("0123456789abcdeg", v));
    EXPECT_FALSE(parse_hash_hex("", v));
}

TEST(JournalJson, MatchIdsAreUrlSafe) {
    EXPECT_TRUE(is_match_id("m-0001"));
    EXPECT_TRUE(is_match_id("0123456789abcdef"));
    EXPECT_TRUE(is_match_id("A_b-9"));
    EXPECT_TRUE(is_match_id(std::string(64, 'a')));
    EXPECT_FALSE(is_match_id(std::string(65, 'a')));
    EXPECT_FALSE(is_match_id(""));
    EXPECT_FALSE(is_match_id("a/b"));
    EXPECT_FALSE(is_match_id("a b"));
    EXPECT_FALSE(is_match_id("a.b"));
}

TEST(JournalJson, AStrokeHasItsShotHashesAndOutcome) {
    const StrokeEntry stroke{3, 1, Shot{250.5, -1.25, 12.5}, 0x0123456789abcdefULL,
                             sample_outcome()};
    EXPECT_EQ(entry_json(stroke), Json::parse(R"({
        "type": "stroke", "time_ms": 1000, "turn": 3, "seat": 1,
        "shot": {"x": 250.5, "angle": -1.25, "power": 12.5},
        "result_hash": "0123456789abcdef",
        "outcome": {"state_hash": "fedcba9876543210", "pocketed": [4, 7],
                    "fouls": ["striker_pocketed"], "scores": [3, -20], "next_seat": 0,
                    "board_end": {"board": 1, "winner_team": 0, "points": 3,
                                  "reason": "board_cleared"}}})"));
    expect_round_trip(stroke);
}

TEST(JournalJson, AGameEndIsRecordedWithADrawAsNull) {
    OutcomeRecord o;
    o.scores = {0, 0};
    o.game_end = rules::GameResult{std::nullopt, rules::RuleCode::BoardsPlayed};
    EXPECT_EQ(outcome_record_to_json(o), Json::parse(R"({
        "state_hash": "0000000000000000", "pocketed": [], "fouls": [], "scores": [0, 0],
        "next_seat": 0, "game_end": {"winner_team": null, "reason": "boards_played"}})"));
    expect_round_trip(ClockExpiredEntry{9, 0, o});
}

TEST(JournalJson, AClockExpiryAndAForfeit) {
    OutcomeRecord o;
    o.scores = {0, 0};
    o.next_seat = 1;
    EXPECT_EQ(entry_json(ClockExpiredEntry{4, 0, o}), Json::parse(R"({
        "type": "clock_expired", "time_ms": 1000, "turn": 4, "seat": 0,
        "outcome": {"state_hash": "0000000000000000", "pocketed": [], "fouls": [],
                    "scores": [0, 0], "next_seat": 1}})"));
    o.game_end = rules::GameResult{1, rules::RuleCode::Forfeit};
    EXPECT_EQ(entry_json(ForfeitEntry{5, 0, ForfeitReason::GraceExpired, o}), Json::parse(R"({
        "type": "forfeit", "time_ms": 1000, "turn": 5, "seat": 0, "reason": "grace_expired",
        "outcome": {"state_hash": "0000000000000000", "pocketed": [], "fouls": [],
                    "scores": [0, 0], "next_seat": 1,
                    "game_end": {"winner_team": 1, "reason": "forfeit"}}})"));
    expect_round_trip(ForfeitEntry{5, 0, ForfeitReason::GraceExpired, o});
    expect_round_trip(ForfeitEntry{5, 1, ForfeitReason::Left, o});
}

TEST(JournalJson, MembershipEntries) {
    EXPECT_EQ(entry_json(SeatJoinedEntry{1, "bea", false}),
              Json::parse(R"({"type": "join", "time_ms": 1000, "seat": 1, "name": "bea",
                              "bot": false})"));
    EXPECT_EQ(entry_json(SeatLeftEntry{0}),
              Json::parse(R"({"type": "leave", "time_ms": 1000, "seat": 0})"));
    EXPECT_EQ(entry_json(SeatDroppedEntry{1}),
              Json::parse(R"({"type": "drop", "time_ms": 1000, "seat": 1})"));
    EXPECT_EQ(entry_json(SeatReturnedEntry{1}),
              Json::parse(R"({"type": "return", "time_ms": 1000, "seat": 1})"));
    EXPECT_EQ(entry_json(RematchEntry{"m-0002"}),
              Json::parse(R"({"type": "rematch", "time_ms": 1000, "next_match": "m-0002"})"));
    expect_round_trip(SeatJoinedEntry{1, "Bot (hard)", true});
    expect_round_trip(SeatLeftEntry{0});
    expect_round_trip(SeatDroppedEntry{1});
    expect_round_trip(SeatReturnedEntry{0});
    expect_round_trip(RematchEntry{"m-0002"});
}

TEST(JournalJson, TheHeadHasEveryRuleAndEveryPhysicsField) {
    const Json j = match_created_to_json(created());
    EXPECT_EQ(j["match_id"], "m-0001");
    EXPECT_TRUE(j["rematch_of"].is_null());
    EXPECT_EQ(j["room"], "ABCDEF");
    EXPECT_EQ(j["rule_set"], "icf");
    EXPECT_EQ(j["rules"].size(), 12U);
    EXPECT_EQ(j["rules"]["first_breaker"], 0);
    EXPECT_EQ(j["physics"].size(), 17U);
    EXPECT_EQ(j["seats"], Json::parse(R"x([{"name": "ann", "bot": false},
                                            {"name": "Bot (medium)", "bot": true}])x"));
    EXPECT_EQ(j["first_turn"], 0);
    EXPECT_EQ(j["versions"], Json::parse(R"({"server": "0.1.0", "physics": 2, "rules": 1})"));
    EXPECT_EQ(j["time_ms"], 1700000000000);
}

TEST(JournalJson, AHeadRoundTripsExactly) {
    MatchCreated c = created();
    c.rematch_of = "m-0000";
    c.first_turn = 77;
    c.rules.first_breaker = 1;
    c.rules.shot_clock_s = 12.5;
    c.physics.disc_restitution = 0.1 + 0.2; // 0.30000000000000004
    c.rule_set = rules::RuleSet::DiscPool;
    const auto decoded = decode_match_created(match_created_to_json(c));
    ASSERT_TRUE(decoded.ok()) << decoded.error->path << ": " << decoded.error->message;
    EXPECT_EQ(decoded.value, c);
}

// Shots decode to the same bits, so a decoded journal replays the same strokes.
TEST(JournalJson, ShotsRoundTripToTheBit) {
    const Shot shots[] = {Shot{std::nextafter(300.0, 0.0), -0.0, 0.1 + 0.2},
                          Shot{123.456789012345678, -std::numbers::pi / 3.0, 24.999999999999996},
                          Shot{5e-324, 1e-300, 0.0}};
    for (const Shot& shot : shots) {
        const StrokeEntry stroke{0, 0, shot, 0, OutcomeRecord{0, {}, {}, {0, 0}, 1, {}, {}}};
        const std::string text = entry_json(stroke).dump();
        const auto decoded = decode_entry(text);
        ASSERT_TRUE(decoded.ok()) << text;
        const Shot& back = std::get<StrokeEntry>(decoded.value.event).shot;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(back.x_px), std::bit_cast<std::uint64_t>(shot.x_px));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(back.angle_rad),
                  std::bit_cast<std::uint64_t>(shot.angle_rad));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(back.power),
                  std::bit_cast<std::uint64_t>(shot.power));
    }
}

TEST(JournalJson, AWholeJournalHasFormatMatchAndEntries) {
    test::JournalRecorder game(created());
    game.member(SeatDroppedEntry{0});
    const Json j = journal_to_json(game.journal());
    EXPECT_EQ(j["format"], 1);
    EXPECT_EQ(j["match"], match_created_to_json(created()));
    EXPECT_EQ(j["entries"].size(), 1U);
    EXPECT_EQ(j.size(), 3U);
}

// docs/protocol.md shows this journal: the standard break, then a dropped connection.
TEST(JournalJson, TheDocumentedExampleIsWhatTheRulesRecord) {
    test::JournalRecorder game(created());
    game.stroke(Shot{300.0, -std::numbers::pi / 2.0, 25.0});
    game.member(SeatDroppedEntry{1});
    const Json j = journal_to_json(game.journal());
    EXPECT_EQ(j["entries"], Json::parse(R"([
        {"type": "stroke", "time_ms": 1700000001500, "turn": 0, "seat": 0,
         "shot": {"x": 300.0, "angle": -1.5707963267948966, "power": 25.0},
         "result_hash": "41f5cfe5483d391f",
         "outcome": {"state_hash": "a379fc4311ddda2e", "pocketed": [], "fouls": [],
                     "scores": [0, 0], "next_seat": 1}},
        {"type": "drop", "time_ms": 1700000003000, "seat": 1}])"));
}

// --- decoding errors ---------------------------------------------------------------------------

constexpr std::string_view kStroke = R"({"type": "stroke", "time_ms": 1, "turn": 0, "seat": 0,
    "shot": {"x": 300, "angle": -1.5, "power": 10}, "result_hash": "0000000000000001",
    "outcome": {"state_hash": "0000000000000002", "pocketed": [], "fouls": [],
                "scores": [0, 0], "next_seat": 1}})";

Json stroke_with(const std::string& pointer, const Json& value) {
    Json j = Json::parse(kStroke);
    j[Json::json_pointer(pointer)] = value;
    return j;
}

Decoded<JournalEntry> decode_json(const Json& j) {
    return decode_journal_entry(j, created(), "entries[0]");
}

TEST(JournalJson, TheSampleStrokeDecodes) {
    const auto d = decode_entry(kStroke);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(std::get<StrokeEntry>(d.value.event).result_hash, 1U);
}

TEST(JournalJson, AMissingFieldIsNamed) {
    Json j = Json::parse(kStroke);
    j.erase("turn");
    expect_error(decode_json(j), "missing_field", "entries[0].turn");
    j = Json::parse(kStroke);
    j["outcome"].erase("state_hash");
    expect_error(decode_json(j), "missing_field", "entries[0].outcome.state_hash");
    expect_error(decode_entry(R"({"time_ms": 1})"), "missing_field", "entries[0].type");
}

TEST(JournalJson, AnUnknownFieldIsNamed) {
    expect_error(decode_json(stroke_with("/extra", 1)), "unknown_field", "entries[0].extra");
    expect_error(decode_json(stroke_with("/outcome/extra", 1)), "unknown_field",
                 "entries[0].outcome.extra");
    expect_error(decode_entry(R"({"type": "leave", "time_ms": 1, "seat": 0, "name": "x"})"),
                 "unknown_field", "entries[0].name");
}

TEST(JournalJson, AnUnknownTypeIsABadValue) {
    expect_error(decode_entry(R"({"type": "teleport", "time_ms": 1})"), "bad_value",
                 "entries[0].type");
    expect_error(decode_entry(R"({"type": 3, "time_ms": 1})"), "wrong_type", "entries[0].type");
}

TEST(JournalJson, SeatsTurnsAndTimesAreRangeChecked) {
    expect_error(decode_json(stroke_with("/seat", 2)), "out_of_range", "entries[0].seat");
    expect_error(decode_json(stroke_with("/seat", -1)), "out_of_range", "entries[0].seat");
    expect_error(decode_json(stroke_with("/turn", -1)), "out_of_range", "entries[0].turn");
    expect_error(decode_json(stroke_with("/time_ms", -5)), "out_of_range", "entries[0].time_ms");
    expect_error(decode_json(stroke_with("/outcome/next_seat", 2)), "out_of_range",
                 "entries[0].outcome.next_seat");
    expect_error(decode_json(stroke_with("/outcome/pocketed", Json::array({19}))), "out_of_range",
                 "entries[0].outcome.pocketed[0]");
    expect_error(decode_entry(R"({"type": "drop", "time_ms": 1, "seat": 2})"), "out_of_range",
                 "entries[0].seat");
}

TEST(JournalJson, HashesMustBeLowercaseHex) {
    expect_error(decode_json(stroke_with("/result_hash", "000000000000000A")), "bad_value",
                 "entries[0].result_hash");
    expect_error(decode_json(stroke_with("/result_hash", 1)), "wrong_type",
                 "entries[0].result_hash");
    expect_error(decode_json(stroke_with("/outcome/state_hash", "12")), "bad_value",
                 "entries[0].outcome.state_hash");
}

TEST(JournalJson, OutcomeListsAreChecked) {
    expect_error(decode_json(stroke_with("/outcome/scores", Json::array({0, 0, 0}))), "wrong_type",
                 "entries[0].outcome.scores");
    expect_error(decode_json(stroke_with("/outcome/fouls", Json::array({"cheating"}))), "bad_value",
                 "entries[0].outcome.fouls[0]");
    expect_error(decode_json(stroke_with("/outcome/fouls", Json::array({1}))), "wrong_type",
                 "entries[0].outcome.fouls[0]");
    expect_error(decode_json(stroke_with("/outcome/board_end", Json::parse(R"({"board": 0})"))),
                 "out_of_range", "entries[0].outcome.board_end.board");
    expect_error(
        decode_json(stroke_with("/outcome/game_end",
                                Json::parse(R"({"winner_team": 2, "reason": "forfeit"})"))),
        "out_of_range", "entries[0].outcome.game_end.winner_team");
    EXPECT_TRUE(decode_json(stroke_with("/outcome/board_end", nullptr)).ok());
}

TEST(JournalJson, ShotsMustBeFiniteNumbers) {
    expect_error(decode_json(stroke_with("/shot/x", "300")), "wrong_type", "entries[0].shot.x");
    Json j = Json::parse(kStroke);
    j["shot"].erase("power");
    expect_error(decode_json(j), "missing_field", "entries[0].shot.power");
}

TEST(JournalJson, NamesReasonsAndIdsAreChecked) {
    expect_error(decode_entry(R"({"type": "join", "time_ms": 1, "seat": 0, "name": "",
                                  "bot": false})"),
                 "bad_value", "entries[0].name");
    expect_error(decode_entry(R"({"type": "join", "time_ms": 1, "seat": 0,
                                  "name": "a\u0001b", "bot": false})"),
                 "bad_value", "entries[0].name");
    expect_error(decode_entry(R"({"type": "forfeit", "time_ms": 1, "turn": 0, "seat": 0,
                                  "reason": "bored", "outcome": {}})"),
                 "bad_value", "entries[0].reason");
    expect_error(decode_entry(R"({"type": "rematch", "time_ms": 1, "next_match": "a/b"})"),
                 "bad_value", "entries[0].next_match");
}

Json journal_json() {
    test::JournalRecorder game(created());
    game.member(SeatDroppedEntry{0});
    return journal_to_json(game.journal());
}

void expect_journal_error(const Json& j, std::string_view code, std::string_view path) {
    const auto d = decode_journal(j);
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error->code, code) << d.error->message;
    EXPECT_EQ(d.error->path, path) << d.error->message;
}

TEST(JournalJson, ANewerFormatIsRefusedWithBothFormatsNamed) {
    Json j = journal_json();
    j["format"] = 2;
    const auto d = decode_journal(j);
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error->code, "unsupported_format");
    EXPECT_EQ(d.error->path, "format");
    EXPECT_EQ(d.error->message, "the journal has format 2; this build reads format 1 and older");
    j["format"] = "1";
    expect_journal_error(j, "wrong_type", "format");
    j["format"] = 0;
    expect_journal_error(j, "out_of_range", "format");
}

TEST(JournalJson, TheHeadIsChecked) {
    Json j = journal_json();
    j["match"]["seats"].erase(1);
    expect_journal_error(j, "wrong_type", "match.seats");
    j = journal_json();
    j["match"]["seats"][0]["name"] = "tab\there";
    expect_journal_error(j, "bad_value", "match.seats[0].name");
    j = journal_json();
    j["match"]["room"] = "abcdef";
    expect_journal_error(j, "bad_value", "match.room");
    j = journal_json();
    j["match"]["rematch_of"] = "no spaces";
    expect_journal_error(j, "bad_value", "match.rematch_of");
    j = journal_json();
    j["match"]["rule_set"] = "snooker";
    expect_journal_error(j, "bad_value", "match.rule_set");
    j = journal_json();
    j["match"]["rules"]["seat_count"] = 3;
    expect_journal_error(j, "invalid_config", "match.rules.seat_count");
    j = journal_json();
    j["match"]["physics"]["coin_radius_px"] = -1;
    expect_journal_error(j, "out_of_range", "match.physics.coin_radius_px");
    j = journal_json();
    j["match"]["versions"]["physics"] = 0;
    expect_journal_error(j, "out_of_range", "match.versions.physics");
    j = journal_json();
    j["match"].erase("versions");
    expect_journal_error(j, "missing_field", "match.versions");
}

TEST(JournalJson, EntriesAreCheckedAgainstTheHead) {
    Json j = journal_json();
    j["entries"][0]["seat"] = 3;
    expect_journal_error(j, "out_of_range", "entries[0].seat");
    j = journal_json();
    j["entries"] = Json::object();
    expect_journal_error(j, "wrong_type", "entries");
    j = journal_json();
    j["unexpected"] = true;
    expect_journal_error(j, "unknown_field", "unexpected");
}

TEST(JournalJson, TextThatIsNotAJournalIsRefused) {
    EXPECT_EQ(decode_journal_text("{\"format\": 1,").error->code, "malformed_json");
    EXPECT_EQ(decode_journal_text("[]").error->code, "wrong_type");
    EXPECT_EQ(decode_journal_text("").error->code, "malformed_json");
    const std::string huge(kMaxJournalBytes + 1, ' ');
    EXPECT_EQ(decode_journal_text(huge).error->code, "too_large");
}

} // namespace
} // namespace carrom::proto
