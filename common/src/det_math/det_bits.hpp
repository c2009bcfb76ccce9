#pragma once
// Bit-level helpers of det_math (carrom/det_math.hpp): pure functions on doubles.

#include <array>
#include <cstddef>
#include <cstdint>

namespace carrom::det::bits {

constexpr std::uint64_t to_bits(double x) {
    return __builtin_bit_cast(std::uint64_t, x);
}

constexpr double from_bits(std::uint64_t b) {
    return __builtin_bit_cast(double, b);
}

// The biased exponent field (0 for zero and subnormals, 2047 for inf and nan).
constexpr int biased_exponent(double x) {
    return static_cast<int>((to_bits(x) >> 52) & 0x7ff);
}

constexpr bool is_nan(double x) {
    return (to_bits(x) & 0x7fffffffffffffffULL) > 0x7ff0000000000000ULL;
}

constexpr bool sign_bit(double x) {
    return (to_bits(x) >> 63) != 0;
}

constexpr double abs(double x) {
    return from_bits(to_bits(x) & 0x7fffffffffffffffULL);
}

constexpr double copy_sign(double magnitude, double sign) {
    return from_bits((to_bits(magnitude) & 0x7fffffffffffffffULL) | (to_bits(sign) & (1ULL << 63)));
}

// 2^k for -1022 <= k <= 1023, exact.
constexpr double pow2(int k) {
    return from_bits(static_cast<std::uint64_t>(k + 1023) << 52);
}

// y * 2^k for a normal y in [0.5, 4) and any k: one rounding only when the result is subnormal.
constexpr double scale_by_pow2(double y, int k) {
    if (k > 1023) {
        return y * pow2(1023) * pow2(k - 1023);
    }
    if (k < -1022) {
        return y * pow2(k + 1000) * pow2(-1000);
    }
    return y * pow2(k);
}

// The nearest integer to x (ties away from zero) for |x| < 2^31.
constexpr int round_to_int(double x) {
    return static_cast<int>(x < 0.0 ? x - 0.5 : x + 0.5);
}

// 1/n! rounded once (the compiler folds the division; n! is exact in a double for n <= 22).
constexpr double inv_factorial(int n) {
    double f = 1.0;
    for (int i = 2; i <= n; ++i) {
        f *= i;
    }
    return 1.0 / f;
}

// c[0] + c[1]*z + c[2]*z^2 + ... by Estrin's scheme: pairs c[2i] + z*c[2i+1], then the same
// on the pairs in z^2, and so on; a fixed order of operations (no fusion), so the result is the
// same bits everywhere, with a dependency chain of log2(N) steps instead of N.
template <std::size_t N> constexpr double estrin(const std::array<double, N>& c, double z) {
    if constexpr (N == 1) {
        return c[0];
    } else {
        std::array<double, (N + 1) / 2> pairs{};
        for (std::size_t i = 0; i < N / 2; ++i) {
            pairs[i] = c[2 * i] + z * c[2 * i + 1];
        }
        if constexpr (N % 2 == 1) {
            pairs[N / 2] = c[N - 1];
        }
        return estrin(pairs, z * z);
    }
}

template <std::size_t N> constexpr double polynomial(const double (&c)[N], double z) {
    std::array<double, N> coefficients{};
    for (std::size_t i = 0; i < N; ++i) {
        coefficients[i] = c[i];
    }
    return estrin(coefficients, z);
}

// a*b = hi + lo exactly (Dekker's product with Veltkamp's split) for |a|, |b| below 2^995 and
// a*b far from underflow.
struct TwoProduct {
    double hi;
    double lo;
};
constexpr TwoProduct two_product(double a, double b) {
    constexpr double kSplit = 134217729.0; // 2^27 + 1
    const double ta = kSplit * a;
    const double a_hi = ta - (ta - a);
    const double a_lo = a - a_hi;
    const double tb = kSplit * b;
    const double b_hi = tb - (tb - b);
    const double b_lo = b - b_hi;
    const double hi = a * b;
    const double lo = ((a_hi * b_hi - hi) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
    return {hi, lo};
}

} // namespace carrom::det::bits
