#pragma once
// The one reader of untrusted JSON in proto/: wire messages, scenes, results, match states and
// journals all read their values through a JsonReader. It checks each value's type, finiteness,
// range and size, keeps the first problem as an Error (error.hpp) naming the value's path, and
// from then on reads nothing: every later read returns a default, so a decoder reads its fields
// in sequence and checks ok() once. Never throws.

#include "carrom/enum_names.hpp"
#include "carrom/proto/error.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace carrom::proto::detail {

// How a reader words its errors; both are documented and pinned by tests.
enum class Wording {
    // Wire messages (docs/protocol.md): every problem is "bad_field" with a sentence that names
    // the field ("field 'options.seats' must be 2 or 4."); text holds no ASCII control characters.
    Wire,
    // Documents (docs/carrom-sim.md): a code per kind of problem (scene_code::*) and a sentence
    // that starts with the value's path ("bodies[3].id must be an integer in [0, 1000000]").
    Document,
};

// Inclusive range [lo, hi]; with lo_open, (lo, hi].
struct Range {
    double lo;
    double hi;
    bool lo_open = false;
    bool contains(double v) const { return (lo_open ? v > lo : v >= lo) && v <= hi; }
};

// "parent.name", or "name" when parent is "" (the document).
std::string field_path(const std::string& parent, std::string_view name);
// "parent[index]".
std::string index_path(const std::string& parent, std::size_t index);

// Value checks without a reader (for values read in bulk, such as snapshot bodies): true and out
// set when value is an integer (a number without fraction or exponent) or a finite number in
// [min, max].
bool read_integer(const nlohmann::json& value, std::int64_t min, std::int64_t max,
                  std::int64_t& out);
bool read_number(const nlohmann::json& value, double min, double max, double& out);

class JsonReader {
public:
    // object must outlive the reader; path is where it lies ("" for the whole document).
    JsonReader(const nlohmann::json& object, std::string path, Wording wording);

    bool ok() const { return !error_.has_value(); }
    const std::optional<Error>& error() const { return error_; }
    // Keeps error unless an earlier one is kept.
    void merge(const std::optional<Error>& error);
    // A reader of value (which lies at path) in this reader's wording; it starts with this
    // reader's error, if any, and so reads nothing after it.
    JsonReader nested(const nlohmann::json& value, std::string path) const;

    const std::string& path() const { return path_; }
    std::string path_of(std::string_view key) const { return field_path(path_, key); }

    // Rejects the value at path_of(key) or at path: requirement is a verb phrase ("must be 2 or
    // 4"); Wire: "field 'P' <requirement>.", Document: "P <requirement>" with document_code.
    void fail(std::string_view key, std::string_view requirement,
              std::string_view document_code = scene_code::kBadValue);
    void fail_at(const std::string& path, std::string_view requirement,
                 std::string_view document_code = scene_code::kBadValue);
    // Rejects value for its type: Document "<path> must be <expected>, not <its type>"
    // (wrong_type); Wire "field '<path>' must be <expected>." or wire_requirement when given.
    void wrong_type(const nlohmann::json& value, const std::string& path, std::string_view expected,
                    std::string_view wire_requirement = {});

    // The value read must be an object whose keys are all in allowed ("unknown_field").
    bool only_keys(std::span<const std::string_view> allowed);
    bool only_keys(std::initializer_list<std::string_view> allowed) {
        return only_keys(std::span(allowed.begin(), allowed.size()));
    }
    // Each key must be present, checked in order ("missing_field").
    bool require(std::initializer_list<std::string_view> keys);
    // The key is present (false once an error is kept).
    bool has(std::string_view key) const;
    // The value of a required key: nullptr, and an error, when it is missing.
    const nlohmann::json* find(std::string_view key);
    // The value of an optional key: nullptr when it is absent or null.
    const nlohmann::json* find_optional(std::string_view key) const;

    // Required fields; each returns a default (0, false, "", fallback, nullptr) after an error.
    std::int64_t integer(std::string_view key, std::int64_t min, std::int64_t max);
    int small_int(std::string_view key, int min, int max);
    double number(std::string_view key, Range range);
    bool boolean(std::string_view key);
    // A string of min..max bytes (Wire: without ASCII control characters).
    std::string text(std::string_view key, std::size_t min_bytes, std::size_t max_bytes);
    // A string that names a value in names. Document wording: "<path> <requirement>", by default
    // `must be "a", "b" or "c"` from names.
    template <class E, std::size_t N>
    E enumeration(std::string_view key, const enum_names::Table<E, N>& names, E fallback,
                  std::string_view requirement = {});
    const nlohmann::json* object(std::string_view key);
    // An array of at most max_items elements.
    const nlohmann::json* array(std::string_view key, std::size_t max_items);
    // An array of at most max_items integers in [min, max] (exactly max_items when exact).
    // Wire: "must hold integers in [min, max]" for any bad item; Document: "must be an array of
    // [at most] N integers" (wrong_type), and an item's own error at its index path.
    std::vector<int> int_array(std::string_view key, int min, int max, std::size_t max_items,
                               bool exact = false);

    // The same checks of a value that lies at path (an array element, a vector component).
    std::int64_t integer_at(const nlohmann::json& value, const std::string& path, std::int64_t min,
                            std::int64_t max);
    double number_at(const nlohmann::json& value, const std::string& path, Range range);
    bool boolean_at(const nlohmann::json& value, const std::string& path);
    std::string text_at(const nlohmann::json& value, const std::string& path, std::size_t min_bytes,
                        std::size_t max_bytes);
    template <class E, std::size_t N>
    E enumeration_at(const nlohmann::json& value, const std::string& path,
                     const enum_names::Table<E, N>& names, E fallback,
                     std::string_view requirement = {});

private:
    // Keeps the first problem: Wire "field '<path>' <wire_requirement>.", Document
    // document_sentence with document_code.
    void reject(std::string_view document_code, const std::string& path,
                std::string_view wire_requirement, std::string document_sentence);
    // Document wording: `must be "a", "b" or "c"`.
    template <class E, std::size_t N>
    static std::string one_of(const enum_names::Table<E, N>& names);

    const nlohmann::json& object_;
    std::string path_;
    Wording wording_;
    std::optional<Error> error_;
};

template <class E, std::size_t N>
E JsonReader::enumeration(std::string_view key, const enum_names::Table<E, N>& names, E fallback,
                          std::string_view requirement) {
    const nlohmann::json* value = find(key);
    return value == nullptr ? fallback
                            : enumeration_at(*value, path_of(key), names, fallback, requirement);
}

template <class E, std::size_t N>
E JsonReader::enumeration_at(const nlohmann::json& value, const std::string& path,
                             const enum_names::Table<E, N>& names, E fallback,
                             std::string_view requirement) {
    if (!ok()) {
        return fallback;
    }
    constexpr std::string_view kWireRequirement = "must be one of the documented names";
    const std::string* text = value.get_ptr<const std::string*>();
    if (text == nullptr) {
        wrong_type(value, path, "a string", kWireRequirement);
        return fallback;
    }
    const std::optional<E> parsed = enum_names::parse(names, *text);
    if (!parsed) {
        reject(scene_code::kBadValue, path, kWireRequirement,
               path + " " + (requirement.empty() ? one_of(names) : std::string(requirement)));
        return fallback;
    }
    return *parsed;
}

template <class E, std::size_t N>
std::string JsonReader::one_of(const enum_names::Table<E, N>& names) {
    std::string out = "must be ";
    for (std::size_t i = 0; i < N; ++i) {
        out += i == 0 ? "" : (i + 1 == N ? " or " : ", ");
        out += '"';
        out += names[i].name;
        out += '"';
    }
    return out;
}

} // namespace carrom::proto::detail
