#include "store/match_store.hpp"

namespace carrom::store {

TokenHash hash_token(std::string_view token) {
    return sha256(token);
}

} // namespace carrom::store
