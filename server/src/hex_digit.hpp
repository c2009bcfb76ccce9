#pragma once
// Private to server/src: the value of one hexadecimal digit, for the percent-decoding of request
// targets (static_site.cpp: paths; match_api.cpp: query values).

namespace carrom::server {

// 0..15, or -1 when c is not a hexadecimal digit (either case).
inline int hex_value(char c) {
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

} // namespace carrom::server
