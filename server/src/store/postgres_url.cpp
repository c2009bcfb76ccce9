#include "store/postgres_url.hpp"

#include <libpq-fe.h>

namespace carrom::store::postgres {

bool is_postgres_url(std::string_view location) {
    return location.substr(0, 13) == "postgresql://" || location.substr(0, 11) == "postgres://";
}

std::string shown_url(const std::string& url) {
    // scheme://user:password@host...: the password is between the first ':' after the scheme
    // and the '@' of the authority.
    const std::size_t start = url.find("://");
    if (start == std::string::npos) {
        return url;
    }
    const std::size_t authority_end = url.find_first_of("/?", start + 3);
    const std::size_t at = url.rfind('@', authority_end);
    if (at == std::string::npos || at < start + 3) {
        return url;
    }
    const std::size_t colon = url.find(':', start + 3);
    if (colon == std::string::npos || colon > at) {
        return url;
    }
    return url.substr(0, colon + 1) + "***" + url.substr(at);
}

std::optional<StoreError> check_url(const std::string& url) {
    char* error = nullptr;
    PQconninfoOption* options = PQconninfoParse(url.c_str(), &error);
    if (options == nullptr) {
        std::string message = error != nullptr ? error : "out of memory";
        PQfreemem(error);
        message = message.substr(0, message.find('\n')); // one line
        return StoreError{std::string(store_code::kBadUrl),
                          shown_url(url) + " is not a PostgreSQL URL libpq accepts: " + message};
    }
    PQconninfoFree(options);
    return std::nullopt;
}

} // namespace carrom::store::postgres
