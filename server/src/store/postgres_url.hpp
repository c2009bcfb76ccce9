#pragma once
// PostgreSQL URLs as the store takes them (postgresql://USER[:PASSWORD]@HOST[:PORT]/DB,
// postgres://, libpq's ?host=/socket/dir and other parameters): recognised, shown without their
// password, and checked by libpq's own parser.

#include "store/match_store.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace carrom::store::postgres {

// A PostgreSQL URL: postgresql://... or postgres://...
bool is_postgres_url(std::string_view location);
// The URL as logs and messages show it: a password in it replaced by "***".
std::string shown_url(const std::string& url);
// A URL libpq cannot parse: a store_bad_url error naming it.
std::optional<StoreError> check_url(const std::string& url);

} // namespace carrom::store::postgres
