#pragma once
// Checks of one enum's name table (carrom/enum_names.hpp), shared by the common and proto tests.

#include "carrom/enum_names.hpp"

#include <gtest/gtest.h>

#include <array>
#include <set>
#include <string>
#include <string_view>

namespace carrom::test {

// The table names enumerator i (every enum here counts from 0 without gaps) expected[i], the exact
// text on the wire and in files; every entry round-trips both ways; names are distinct; the enum's
// to_string and parse function agree with the table; a longer text parses as nothing.
template <class E, std::size_t N, class ToString, class Parse>
void expect_table(const enum_names::Table<E, N>& table, ToString to_string, Parse parse,
                  const std::array<std::string_view, N>& expected) {
    std::set<std::string_view> names;
    for (std::size_t i = 0; i < N; ++i) {
        const E value = static_cast<E>(i);
        const auto name = enum_names::name_of(table, value);
        ASSERT_TRUE(name.has_value()) << "enumerator " << i << " has no name";
        EXPECT_EQ(*name, expected[i]);
        EXPECT_EQ(enum_names::parse(table, *name), value) << *name;
        EXPECT_EQ(to_string(value), *name);
        E parsed = static_cast<E>((i + 1) % N);
        EXPECT_TRUE(parse(*name, parsed)) << *name;
        EXPECT_EQ(parsed, value) << *name;
        EXPECT_TRUE(names.insert(*name).second) << "duplicate name " << *name;
        E unchanged = value;
        EXPECT_FALSE(parse(std::string(*name) + "x", unchanged)) << *name;
        EXPECT_EQ(unchanged, value);
    }
    EXPECT_EQ(to_string(static_cast<E>(N)), "unknown");
}

// The parse function of an enum whose header offers only to_string.
template <class E, std::size_t N> auto parser_of(const enum_names::Table<E, N>& table) {
    return [&table](std::string_view text, E& out) {
        return enum_names::parse_into(table, text, out);
    };
}

} // namespace carrom::test
