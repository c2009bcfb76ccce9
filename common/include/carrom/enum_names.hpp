#pragma once
// The one way to give an enum names: a constexpr table of {value, name} pairs, read both ways by
// name_of and parse. Every enum with names on the wire or in files (body and event kinds, rule
// sets, rule codes, seat sides, the protocol's enums) keeps its table next to its to_string.
// Invariants a table keeps: each value and each name appears once; names are the exact strings
// written to the wire and to files.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace carrom::enum_names {

template <class E> struct Entry {
    E value;
    std::string_view name;
};

template <class E, std::size_t N> using Table = std::array<Entry<E>, N>;

// The name of value, or nullopt when the table does not list it.
template <class E, std::size_t N>
constexpr std::optional<std::string_view> name_of(const Table<E, N>& table, E value) {
    for (const Entry<E>& entry : table) {
        if (entry.value == value) {
            return entry.name;
        }
    }
    return std::nullopt;
}

// The value named text (exact, case-sensitive), or nullopt.
template <class E, std::size_t N>
constexpr std::optional<E> parse(const Table<E, N>& table, std::string_view text) {
    for (const Entry<E>& entry : table) {
        if (entry.name == text) {
            return entry.value;
        }
    }
    return std::nullopt;
}

// The to_string of an enum: its name, or "unknown" for a value outside the table.
template <class E, std::size_t N>
constexpr std::string_view name_or_unknown(const Table<E, N>& table, E value) {
    return name_of(table, value).value_or("unknown");
}

// The bool-and-out-parameter form the parse functions of the enums keep: out is set only when
// text names a value.
template <class E, std::size_t N>
constexpr bool parse_into(const Table<E, N>& table, std::string_view text, E& out) {
    const std::optional<E> value = parse(table, text);
    if (value) {
        out = *value;
    }
    return value.has_value();
}

} // namespace carrom::enum_names
