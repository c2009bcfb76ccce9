#pragma once
// Private to net/src: a URL as error sentences show it (url.cpp, http_get.cpp).

#include <string>
#include <string_view>

namespace carrom::net {

// The URL in single quotes, its first 80 bytes ("..." after them), control bytes as '?'.
std::string quoted_url(std::string_view url);

} // namespace carrom::net
