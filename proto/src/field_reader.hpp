#pragma once
// Reads typed, range-checked fields from untrusted JSON. The first problem is kept as a
// "bad_field" error naming the field path; every later read returns a default, so decoders read
// all their fields in sequence and check ok() once at the end. Never throws.

#include "carrom/proto/error.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace carrom::proto::detail {

class FieldReader {
public:
    // `object` must outlive the reader; `path` prefixes field names in messages ("options.").
    FieldReader(const nlohmann::json& object, std::string path);

    bool ok() const { return !error_.has_value(); }
    const std::optional<Error>& error() const { return error_; }
    void fail(std::string_view key, std::string_view requirement);
    // Takes a nested reader's error, if any.
    void merge(const FieldReader& child);

    bool has(std::string_view key) const;
    std::int64_t integer(std::string_view key, std::int64_t min, std::int64_t max);
    int small_int(std::string_view key, int min, int max);
    double number(std::string_view key, double min, double max);
    bool boolean(std::string_view key);
    // A string of min..max bytes without ASCII control characters.
    std::string text(std::string_view key, std::size_t min_bytes, std::size_t max_bytes);
    // A string accepted by parse(text, out) for the enum E.
    template <class E> E enumeration(std::string_view key, E fallback);
    // A nested object (nullptr and an error when absent or not an object).
    const nlohmann::json* object(std::string_view key);
    // An array of at most max_items elements (nullptr and an error otherwise).
    const nlohmann::json* array(std::string_view key, std::size_t max_items);
    std::vector<int> int_array(std::string_view key, int min, int max, std::size_t max_items);

    std::string field_name(std::string_view key) const;

private:
    const nlohmann::json* find(std::string_view key); // error when missing
    const nlohmann::json& object_;
    std::string path_;
    std::optional<Error> error_;
};

// Value-level checks, shared with array element readers.
bool read_integer(const nlohmann::json& value, std::int64_t min, std::int64_t max,
                  std::int64_t& out);
bool read_number(const nlohmann::json& value, double min, double max, double& out);
std::string range_text(double min, double max);
std::string range_text(std::int64_t min, std::int64_t max);

template <class E> E FieldReader::enumeration(std::string_view key, E fallback) {
    const nlohmann::json* value = find(key);
    if (value == nullptr) {
        return fallback;
    }
    E out = fallback;
    const std::string* text = value->get_ptr<const std::string*>();
    if (text == nullptr || !parse(*text, out)) {
        fail(key, "must be one of the documented names");
        return fallback;
    }
    return out;
}

} // namespace carrom::proto::detail
