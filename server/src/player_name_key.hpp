#pragma once
// Private to server/src: how identified players' names are compared (docs/ratings.md, "Names").
// Two names are the same name when their keys are equal: the key is the name's Unicode NFKC
// case fold with default-ignorable characters removed (utf8proc_NFKC_Casefold: "ASHA", "asha"
// and fullwidth "Ａｓｈａ" are one name, as are a decomposed and a precomposed "é"), with runs of
// white space made one space and trimmed. Boost-free.

#include <optional>
#include <string>
#include <string_view>

namespace carrom::server {

// The comparison key of a name; none when the name is not valid UTF-8 or its key is empty
// (only ignorable characters and spaces).
std::optional<std::string> player_name_key(std::string_view name);

} // namespace carrom::server
