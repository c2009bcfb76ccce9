// det::log and det::log1p (carrom/det_math.hpp): 1 + f = 2^k * m with m in [sqrt2/2, sqrt2),
// f = m - 1 exact, then log(1 + f) = 2*atanh(s) with s = f / (2 + f), |s| <= 0.1716: the series
// 2s + 2s^3/3 + ... + 2s^23/23 (truncation below 2^-62 relative), arranged as
// f - (f^2/2 - s*(f^2/2 + R)) (the identity 2s = f - s*f) so that the large part f is exact.
// docs/decisions/006-deterministic-math.md.

#include "carrom/det_math.hpp"
#include "det_bits.hpp"

namespace carrom::det {
namespace {

constexpr double kLogLn2Hi = 0x1.62e42ff000000p-1;   // ln 2 to 32 bits: k*kLogLn2Hi exact
constexpr double kLogLn2Lo = -0x1.718432a1b0e26p-35; // ln 2 - kLogLn2Hi
constexpr double kSqrt2 = 0x1.6a09e667f3bcdp+0;
constexpr double kLog1pDirectLow = -0x1.2bec333018867p-2; // sqrt2/2 - 1
constexpr double kLog1pDirectHigh = 0x1.a827999fcef32p-2; // sqrt2 - 1
constexpr double kQuietNan = __builtin_bit_cast(double, 0x7ff8000000000000ULL);
constexpr double kInfinity = __builtin_bit_cast(double, 0x7ff0000000000000ULL);

// (log(1+f) - 2s) / s = R(s^2), R(z) = z * (2/3 + 2z/5 + ... + 2z^10/23).
constexpr double kAtanhTail[] = {2.0 / 3.0,  2.0 / 5.0,  2.0 / 7.0,  2.0 / 9.0,
                                 2.0 / 11.0, 2.0 / 13.0, 2.0 / 15.0, 2.0 / 17.0,
                                 2.0 / 19.0, 2.0 / 21.0, 2.0 / 23.0};

// k*ln2 + log(1 + f) + c for f in [sqrt2/2 - 1, sqrt2 - 1) and a small correction c.
double log_reduced(int k, double f, double c) {
    const double s = f / (2.0 + f);
    const double z = s * s;
    const double tail = z * bits::polynomial(kAtanhTail, z);
    const double half_f_squared = 0.5 * f * f;
    const double dk = k;
    return dk * kLogLn2Hi +
           (f - (half_f_squared - (s * (half_f_squared + tail) + (dk * kLogLn2Lo + c))));
}

// u = 2^k * m with m in [sqrt2/2, sqrt2), for a positive normal u.
struct Decomposition {
    int k;
    double m;
};
Decomposition decompose(double u) {
    int k = bits::biased_exponent(u) - 1023;
    double m = bits::from_bits((bits::to_bits(u) & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
    if (m >= kSqrt2) {
        m *= 0.5;
        k += 1;
    }
    return {k, m};
}

} // namespace

double log(double x) {
    if (bits::is_nan(x)) {
        return x + x;
    }
    if (x == 0.0) {
        return -kInfinity;
    }
    if (x < 0.0) {
        return kQuietNan;
    }
    if (x == kInfinity) {
        return x;
    }
    int extra_k = 0;
    if (bits::biased_exponent(x) == 0) { // subnormal: scale into the normal range, exactly
        x *= 0x1p54;
        extra_k = -54;
    }
    const Decomposition d = decompose(x);
    return log_reduced(d.k + extra_k, d.m - 1.0, 0.0);
}

double log1p(double x) {
    if (bits::is_nan(x)) {
        return x + x;
    }
    if (x == -1.0) {
        return -kInfinity;
    }
    if (x < -1.0) {
        return kQuietNan;
    }
    if (x == kInfinity) {
        return x;
    }
    if (bits::abs(x) < 0x1p-54) {
        return x; // keeps -0
    }
    if (x >= kLog1pDirectLow && x < kLog1pDirectHigh) {
        return log_reduced(0, x, 0.0);
    }
    // u = 1 + x rounded; c/u corrects log(u) to log(1 + x) (c = 1 + x - u, exact).
    double u = x;
    double c = 0.0;
    if (x < 0x1p53) {
        u = 1.0 + x;
        c = (u >= 2.0 ? 1.0 - (u - x) : x - (u - 1.0)) / u;
    }
    const Decomposition d = decompose(u);
    return log_reduced(d.k, d.m - 1.0, c);
}

} // namespace carrom::det
