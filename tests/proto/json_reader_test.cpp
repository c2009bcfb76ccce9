// JsonReader, the one reader of untrusted JSON in proto/: each check's exact error in both
// wordings (Wire: docs/protocol.md, Document: docs/carrom-sim.md), the paths of nested values, and
// that the first problem is kept while later reads return defaults.

#include "json_reader.hpp"

#include "carrom/body.hpp"
#include "carrom/scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <ostream>

namespace carrom::proto {
// Failures print the error's fields.
void PrintTo(const Error& error, std::ostream* out) {
    *out << "{" << error.code << ", \"" << error.message << "\", " << error.path << "}";
}
} // namespace carrom::proto

namespace carrom::proto::detail {
namespace {

using nlohmann::json;

Error wire(std::string message, std::string path) {
    return Error{"bad_field", std::move(message), std::move(path)};
}
Error document(std::string_view code, std::string message, std::string path) {
    return Error{std::string(code), std::move(message), std::move(path)};
}

// --- Wire wording ---

TEST(JsonReaderWire, AMissingFieldIsRequired) {
    const json j = json::object();
    JsonReader r(j, "", Wording::Wire);
    EXPECT_EQ(r.integer("turn", 0, 10), 0);
    EXPECT_EQ(r.error(), wire("field 'turn' is required.", "turn"));
}

TEST(JsonReaderWire, AFieldOfANonObjectBelongsToAValueThatMustBeAnObject) {
    const json j = 5;
    JsonReader r(j, "options", Wording::Wire);
    r.boolean("fast");
    EXPECT_EQ(r.error(), wire("field 'options.fast' belongs to a value that must be an object.",
                              "options.fast"));
}

TEST(JsonReaderWire, IntegersOfTheWrongTypeOrOutOfRangeGetOneSentence) {
    for (const json& value : {json("3"), json(3.0), json(true), json(11), json(-1),
                              json(std::numeric_limits<std::uint64_t>::max())}) {
        const json j = {{"n", value}};
        JsonReader r(j, "", Wording::Wire);
        EXPECT_EQ(r.integer("n", 0, 10), 0) << value;
        EXPECT_EQ(r.error(), wire("field 'n' must be an integer in [0, 10].", "n")) << value;
    }
}

TEST(JsonReaderWire, IntegersInRangeAreRead) {
    const json j = {{"a", 0}, {"b", 10}, {"c", -4}, {"d", 9007199254740991}};
    JsonReader r(j, "", Wording::Wire);
    EXPECT_EQ(r.integer("a", 0, 10), 0);
    EXPECT_EQ(r.small_int("b", 0, 10), 10);
    EXPECT_EQ(r.integer("c", -5, 5), -4);
    EXPECT_EQ(r.integer("d", 0, 9007199254740991), 9007199254740991);
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderWire, NumbersPrintTheirRangeWithPercentG) {
    for (const json& value : {json("1"), json(nullptr), json(-0.5), json(1e7)}) {
        const json j = {{"x", value}};
        JsonReader r(j, "", Wording::Wire);
        EXPECT_EQ(r.number("x", {0.0, 1e6}), 0.0) << value;
        EXPECT_EQ(r.error(), wire("field 'x' must be a finite number in [0, 1e+06].", "x"));
    }
    const json j = {{"x", 2.5}, {"y", 7}};
    JsonReader r(j, "", Wording::Wire);
    EXPECT_EQ(r.number("x", {-3.0, 3.0}), 2.5);
    EXPECT_EQ(r.number("y", {0.0, 10.0}), 7.0);
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderWire, Booleans) {
    const json j = {{"yes", true}, {"no", 0}};
    JsonReader r(j, "", Wording::Wire);
    EXPECT_TRUE(r.boolean("yes"));
    EXPECT_FALSE(r.boolean("no"));
    EXPECT_EQ(r.error(), wire("field 'no' must be true or false.", "no"));
}

TEST(JsonReaderWire, TextChecksTypeLengthAndControlCharacters) {
    const auto error_of = [](const json& value, std::size_t min, std::size_t max) {
        const json j = {{"s", value}};
        JsonReader r(j, "", Wording::Wire);
        EXPECT_EQ(r.text("s", min, max), "");
        return r.error();
    };
    EXPECT_EQ(error_of(7, 0, 5), wire("field 's' must be a string.", "s"));
    EXPECT_EQ(error_of("abcdef", 0, 5), wire("field 's' must be 0 to 5 bytes long.", "s"));
    EXPECT_EQ(error_of("", 1, 5), wire("field 's' must be 1 to 5 bytes long.", "s"));
    EXPECT_EQ(error_of("abc", 6, 6), wire("field 's' must be exactly 6 bytes long.", "s"));
    EXPECT_EQ(error_of("a\nb", 0, 5), wire("field 's' must not contain control characters.", "s"));
    EXPECT_EQ(error_of("a\x7f", 0, 5), wire("field 's' must not contain control characters.", "s"));
    const json j = {{"s", "K7M2QX"}};
    JsonReader r(j, "", Wording::Wire);
    EXPECT_EQ(r.text("s", 6, 6), "K7M2QX");
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderWire, EnumerationsAcceptTheTablesNamesOnly) {
    for (const json& value : {json("Queen"), json("king"), json(2)}) {
        const json j = {{"kind", value}};
        JsonReader r(j, "", Wording::Wire);
        EXPECT_EQ(r.enumeration("kind", kBodyKindNames, BodyKind::White), BodyKind::White);
        EXPECT_EQ(r.error(), wire("field 'kind' must be one of the documented names.", "kind"));
    }
    const json j = {{"kind", "queen"}};
    JsonReader r(j, "", Wording::Wire);
    EXPECT_EQ(r.enumeration("kind", kBodyKindNames, BodyKind::White), BodyKind::Queen);
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderWire, ObjectsAndArrays) {
    const json j = {{"o", json::array()}, {"a", {1, 2, 3}}, {"b", "x"}};
    {
        JsonReader r(j, "", Wording::Wire);
        EXPECT_EQ(r.object("o"), nullptr);
        EXPECT_EQ(r.error(), wire("field 'o' must be an object.", "o"));
    }
    {
        JsonReader r(j, "", Wording::Wire);
        EXPECT_EQ(r.array("a", 2), nullptr);
        EXPECT_EQ(r.error(), wire("field 'a' must have at most 2 items.", "a"));
    }
    {
        JsonReader r(j, "", Wording::Wire);
        EXPECT_EQ(r.array("b", 2), nullptr);
        EXPECT_EQ(r.error(), wire("field 'b' must be an array.", "b"));
    }
    {
        JsonReader r(j, "", Wording::Wire);
        EXPECT_EQ(r.int_array("a", 1, 2, 3), std::vector<int>{});
        EXPECT_EQ(r.error(), wire("field 'a' must hold integers in [1, 2].", "a"));
    }
    JsonReader r(j, "", Wording::Wire);
    EXPECT_EQ(r.int_array("a", 1, 3, 3), (std::vector<int>{1, 2, 3}));
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderWire, FailWordsARequirement) {
    const json j = {{"seats", 3}};
    JsonReader r(j, "", Wording::Wire);
    r.fail("seats", "must be 2 or 4");
    EXPECT_EQ(r.error(), wire("field 'seats' must be 2 or 4.", "seats"));
}

TEST(JsonReaderWire, NestedReadersNameTheWholePath) {
    const json j = {{"bot", {{"seats", {1, 5}}}}};
    JsonReader r(j, "", Wording::Wire);
    const json* bot = r.object("bot");
    ASSERT_NE(bot, nullptr);
    JsonReader child = r.nested(*bot, r.path_of("bot"));
    child.int_array("seats", 1, 3, 3);
    r.merge(child.error());
    EXPECT_EQ(r.error(), wire("field 'bot.seats' must hold integers in [1, 3].", "bot.seats"));
}

TEST(JsonReaderWire, TheFirstProblemIsKeptAndLaterReadsReturnDefaults) {
    const json j = {{"a", "x"}, {"b", 4}, {"c", true}, {"d", "text"}, {"e", {{"f", 1}}}};
    JsonReader r(j, "", Wording::Wire);
    r.integer("a", 0, 9);
    const Error first = *r.error();
    EXPECT_EQ(r.integer("b", 0, 9), 0);
    EXPECT_FALSE(r.boolean("c"));
    EXPECT_EQ(r.text("d", 0, 9), "");
    EXPECT_EQ(r.object("e"), nullptr);
    EXPECT_FALSE(r.has("b"));
    r.integer("missing", 0, 1);
    r.fail("b", "must be odd");
    r.merge(Error{"other", "other", ""});
    EXPECT_EQ(r.error(), first);
    JsonReader child = r.nested(j["e"], "e");
    EXPECT_EQ(child.integer("f", 0, 9), 0);
    EXPECT_EQ(child.error(), first);
}

// --- Document wording ---

TEST(JsonReaderDocument, AMissingFieldIsNamedWithItsParent) {
    const json j = json::object();
    JsonReader top(j, "", Wording::Document);
    top.number("x", {0.0, 1.0});
    EXPECT_EQ(top.error(), document("missing_field", "the document needs the field 'x'", "x"));
    JsonReader nested(j, "bodies[2]", Wording::Document);
    nested.integer("id", 0, 9);
    EXPECT_EQ(nested.error(),
              document("missing_field", "bodies[2] needs the field 'id'", "bodies[2].id"));
}

TEST(JsonReaderDocument, AFieldOfANonObjectIsMissing) {
    const json j = json::array();
    JsonReader r(j, "entries[0]", Wording::Document);
    r.text("type", 0, 32);
    EXPECT_EQ(r.error(),
              document("missing_field", "entries[0] needs the field 'type'", "entries[0].type"));
}

TEST(JsonReaderDocument, RequireChecksEveryKeyInOrderBeforeAnyValue) {
    const json j = {{"id", "seven"}, {"kind", "black"}};
    JsonReader r(j, "bodies[0]", Wording::Document);
    EXPECT_FALSE(r.require({"id", "kind", "pos"}));
    EXPECT_EQ(r.error(),
              document("missing_field", "bodies[0] needs the field 'pos'", "bodies[0].pos"));
}

TEST(JsonReaderDocument, WrongTypesNameWhatWasFound) {
    const auto error_of = [](const json& value) {
        const json j = {{"id", value}};
        JsonReader r(j, "b", Wording::Document);
        r.integer("id", 0, 9);
        return r.error();
    };
    EXPECT_EQ(error_of("1"), document("wrong_type", "b.id must be an integer, not string", "b.id"));
    EXPECT_EQ(error_of(1.5),
              document("wrong_type", "b.id must be an integer, not a number", "b.id"));
    EXPECT_EQ(error_of(nullptr),
              document("wrong_type", "b.id must be an integer, not null", "b.id"));
    EXPECT_EQ(error_of(json::object()),
              document("wrong_type", "b.id must be an integer, not object", "b.id"));
    EXPECT_EQ(error_of(false),
              document("wrong_type", "b.id must be an integer, not boolean", "b.id"));
}

TEST(JsonReaderDocument, IntegersOutOfRange) {
    for (const json& value :
         {json(10), json(-1), json(std::numeric_limits<std::uint64_t>::max())}) {
        const json j = {{"seat", value}};
        JsonReader r(j, "", Wording::Document);
        EXPECT_EQ(r.integer("seat", 0, 9), 0);
        EXPECT_EQ(r.error(), document("out_of_range", "seat must be an integer in [0, 9]", "seat"));
    }
}

TEST(JsonReaderDocument, NumbersCheckTypeFinitenessAndRange) {
    const auto error_of = [](const json& value, Range range) {
        const json j = {{"x", value}};
        JsonReader r(j, "shot", Wording::Document);
        EXPECT_EQ(r.number("x", range), 0.0);
        return r.error();
    };
    EXPECT_EQ(error_of("1", {0.0, 1.0}),
              document("wrong_type", "shot.x must be a number, not string", "shot.x"));
    EXPECT_EQ(error_of(std::nan(""), {0.0, 1.0}),
              document("not_finite", "shot.x must be a finite number", "shot.x"));
    EXPECT_EQ(error_of(1.5, {0.0, 1.0}),
              document("out_of_range", "shot.x = 1.5 is outside [0, 1]", "shot.x"));
    EXPECT_EQ(error_of(0.0, {0.0, 1e5, true}),
              document("out_of_range", "shot.x = 0 is outside (0, 1e+05]", "shot.x"));
    EXPECT_EQ(error_of(0.1, {0.25, 0.75}),
              document("out_of_range", "shot.x = 0.1 is outside [0.25, 0.75]", "shot.x"));
    const json j = {{"x", 1e5}};
    JsonReader r(j, "", Wording::Document);
    EXPECT_EQ(r.number("x", {0.0, 1e5, true}), 1e5);
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderDocument, BooleansAndText) {
    const json j = {{"on", "yes"}, {"name", "abcd"}, {"line", "a\nb"}};
    {
        JsonReader r(j, "", Wording::Document);
        r.boolean("on");
        EXPECT_EQ(r.error(), document("wrong_type", "on must be true or false, not string", "on"));
    }
    {
        JsonReader r(j, "", Wording::Document);
        r.text("name", 0, 3);
        EXPECT_EQ(r.error(), document("out_of_range", "name is longer than 3 bytes", "name"));
    }
    {
        JsonReader r(j, "", Wording::Document);
        r.text("on", 5, 9);
        EXPECT_EQ(r.error(), document("out_of_range", "on is shorter than 5 bytes", "on"));
    }
    JsonReader r(j, "", Wording::Document);
    EXPECT_EQ(r.text("line", 0, 9), "a\nb"); // documents may hold control characters
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderDocument, EnumerationsListTheNamesOrSayTheirRequirement) {
    const json j = {{"kind", "king"}, {"reason", "fluke"}, {"number", 3}};
    {
        JsonReader r(j, "bodies[1]", Wording::Document);
        EXPECT_EQ(r.enumeration("kind", kBodyKindNames, BodyKind::White), BodyKind::White);
        EXPECT_EQ(r.error(),
                  document("bad_value",
                           "bodies[1].kind must be \"black\", \"white\", \"queen\" or \"striker\"",
                           "bodies[1].kind"));
    }
    {
        JsonReader r(j, "", Wording::Document);
        r.enumeration("reason", kBodyKindNames, BodyKind::White, "is not a rule code");
        EXPECT_EQ(r.error(), document("bad_value", "reason is not a rule code", "reason"));
    }
    {
        JsonReader r(j, "", Wording::Document);
        r.enumeration("number", kBodyKindNames, BodyKind::White);
        EXPECT_EQ(r.error(),
                  document("wrong_type", "number must be a string, not a number", "number"));
    }
    const json two = {{"b", "top"}};
    JsonReader r(two, "", Wording::Document);
    EXPECT_EQ(r.enumeration("b", kBaselineNames, carrom::Baseline::Bottom), carrom::Baseline::Top);
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderDocument, OnlyKeysRejectsUnknownKeysAndNonObjects) {
    const json j = {{"x", 1}, {"zzz", 2}};
    {
        JsonReader r(j, "config", Wording::Document);
        EXPECT_FALSE(r.only_keys({"x", "y"}));
        EXPECT_EQ(r.error(),
                  document("unknown_field", "unknown field 'zzz' in config", "config.zzz"));
    }
    {
        JsonReader r(j, "", Wording::Document);
        EXPECT_FALSE(r.only_keys({"x"}));
        EXPECT_EQ(r.error(),
                  document("unknown_field", "unknown field 'zzz' in the document", "zzz"));
    }
    {
        const json list = {1, 2};
        JsonReader r(list, "config", Wording::Document);
        EXPECT_FALSE(r.only_keys({"x"}));
        EXPECT_EQ(r.error(),
                  document("wrong_type", "config must be an object, not array", "config"));
    }
    JsonReader r(j, "", Wording::Document);
    EXPECT_TRUE(r.only_keys({"zzz", "x", "y"}));
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderDocument, IntegerArraysNameTheirSizeAndTheBadItemsIndex) {
    const json j = {{"scores", {1, 2, 3}}, {"dues", {0, "1"}}, {"ids", {4, 99}}};
    const auto error_of = [&j](std::string_view key, int max, std::size_t items, bool exact) {
        JsonReader r(j, "state", Wording::Document);
        r.int_array(key, 0, max, items, exact);
        return r.error();
    };
    EXPECT_EQ(
        error_of("scores", 9, 2, true),
        document("wrong_type", "state.scores must be an array of 2 integers", "state.scores"));
    EXPECT_EQ(error_of("scores", 9, 2, false),
              document("wrong_type", "state.scores must be an array of at most 2 integers",
                       "state.scores"));
    EXPECT_EQ(
        error_of("dues", 9, 2, true),
        document("wrong_type", "state.dues[1] must be an integer, not string", "state.dues[1]"));
    EXPECT_EQ(
        error_of("ids", 18, 19, false),
        document("out_of_range", "state.ids[1] must be an integer in [0, 18]", "state.ids[1]"));
    JsonReader r(j, "", Wording::Document);
    EXPECT_EQ(r.int_array("scores", 0, 9, 3, true), (std::vector<int>{1, 2, 3}));
    EXPECT_TRUE(r.ok());
}

TEST(JsonReaderDocument, FailAndWrongTypeUseThePathAndTheGivenCode) {
    const json j = {{"pos", {1, 2, 3}}};
    {
        JsonReader r(j, "bodies[0]", Wording::Document);
        r.fail("pos", "must be [x, y], not an array of 3", scene_code::kWrongType);
        EXPECT_EQ(r.error(),
                  document("wrong_type", "bodies[0].pos must be [x, y], not an array of 3",
                           "bodies[0].pos"));
    }
    {
        JsonReader r(j, "", Wording::Document);
        r.fail_at("", "must be a JSON object");
        EXPECT_EQ(r.error(), document("bad_value", "the document must be a JSON object", ""));
    }
    JsonReader r(j, "", Wording::Document);
    r.wrong_type(j["pos"], "pos", "[x, y]");
    EXPECT_EQ(r.error(), document("wrong_type", "pos must be [x, y], not array", "pos"));
}

TEST(JsonReaderDocument, OptionalFieldsAndPresence) {
    const json j = {{"a", nullptr}, {"b", 2}};
    JsonReader r(j, "", Wording::Document);
    EXPECT_EQ(r.find_optional("a"), nullptr);
    EXPECT_EQ(r.find_optional("c"), nullptr);
    ASSERT_NE(r.find_optional("b"), nullptr);
    EXPECT_EQ(*r.find_optional("b"), 2);
    EXPECT_TRUE(r.has("a"));
    EXPECT_FALSE(r.has("c"));
    r.integer("a", 0, 1);
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(r.has("b"));
    EXPECT_EQ(r.find_optional("b"), nullptr);
}

TEST(JsonReaderDocument, NestedPathsJoinWithDotsAndIndices) {
    EXPECT_EQ(field_path("", "x"), "x");
    EXPECT_EQ(field_path("bodies[3]", "vel"), "bodies[3].vel");
    EXPECT_EQ(index_path("entries", 4), "entries[4]");
    const json j = {{"match", {{"versions", {{"physics", 0}}}}}};
    JsonReader r(j, "", Wording::Document);
    JsonReader match = r.nested(j["match"], r.path_of("match"));
    JsonReader versions = match.nested(j["match"]["versions"], match.path_of("versions"));
    versions.integer("physics", 1, 1000);
    r.merge(versions.error());
    EXPECT_EQ(r.error(),
              document("out_of_range", "match.versions.physics must be an integer in [1, 1000]",
                       "match.versions.physics"));
}

} // namespace
} // namespace carrom::proto::detail
