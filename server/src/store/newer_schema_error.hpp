#pragma once
// The store_newer_schema refusal both backends give, in the same words.

#include "store/match_store.hpp"

#include <string>

namespace carrom::store {

// "WHERE was written by a newer carrom-server (schema version FOUND; this one knows up to
// KNOWN)".
StoreError newer_schema_error(const std::string& where, int found, int known);

} // namespace carrom::store
