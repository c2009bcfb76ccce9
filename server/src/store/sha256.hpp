#pragma once
// SHA-256 (FIPS 180-4), for hashing resume tokens before they are stored: the store keeps
// sha256(token), never the token, so a copy of the database does not let anyone take a seat.
// A compact implementation of its own (about 100 lines, checked against the FIPS 180-4 and NIST
// CAVP test vectors in tests/store/sha256_test.cpp) rather than a dependency on OpenSSL's
// libcrypto for one hash of a 32-byte string per seat.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace carrom::store {

using Sha256Digest = std::array<std::uint8_t, 32>;

Sha256Digest sha256(std::string_view data);
// 64 lowercase hex digits.
std::string to_hex(const Sha256Digest& digest);

} // namespace carrom::store
