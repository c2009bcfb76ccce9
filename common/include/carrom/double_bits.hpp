#pragma once
// The 64 bits of a double, for hashes and bit-for-bit comparisons. A helper rather than
// std::bit_cast: the libc++ of Debian's emscripten (3.1.6), which builds common/ for the browser
// (docs/web.md, "The engine in the page"), has no <bit> bit_cast; the compiler builtin is the
// same operation in GCC and Clang.

#include <cstdint>

namespace carrom {

constexpr std::uint64_t double_bits(double x) {
    return __builtin_bit_cast(std::uint64_t, x);
}

} // namespace carrom
