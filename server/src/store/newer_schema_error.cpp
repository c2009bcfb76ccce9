#include "store/newer_schema_error.hpp"

namespace carrom::store {

StoreError newer_schema_error(const std::string& where, int found, int known) {
    return StoreError{std::string(store_code::kNewerSchema),
                      where + " was written by a newer carrom-server (schema version " +
                          std::to_string(found) + "; this one knows up to " +
                          std::to_string(known) + ")"};
}

} // namespace carrom::store
