// det::exp and det::expm1 (carrom/det_math.hpp): Cody and Waite's reduction x = k*ln2 + r with
// |r| <= ln2/2 (ln2 split in two parts so that k*ln2_hi is exact), the Taylor series of
// exp(r) - 1 - r to degree 14 (truncation below 2^-62 relative), and the result scaled by 2^k.
// The roundings that matter are kept as exact sums (two-sum) so that only the last addition
// rounds. docs/decisions/006-deterministic-math.md.

#include "carrom/det_math.hpp"
#include "det_bits.hpp"

namespace carrom::det {
namespace {

using bits::inv_factorial;

constexpr double kLn2Hi = 0x1.62e42ff000000p-1;   // ln 2 to 32 bits: k*kLn2Hi exact, |k| < 2^21
constexpr double kLn2Lo = -0x1.718432a1b0e26p-35; // ln 2 - kLn2Hi
constexpr double kInvLn2 = 0x1.71547652b82fep+0;
constexpr double kHalfLn2 = 0x1.62e42fefa39efp-2;
constexpr double kExpOverflow = 0x1.62e42fefa39efp+9;    // the largest x with finite exp(x)
constexpr double kExpUnderflow = -0x1.74910d52d3051p+9;  // below it exp(x) rounds to +0
constexpr double kExpm1MinusOne = -0x1.3687a9f1af2b1p+5; // -56 ln 2: below it expm1(x) is -1

// (exp(r) - 1 - r) / r^2 = 1/2! + r/3! + ... + r^12/14!.
constexpr double kExpTail[] = {
    inv_factorial(2),  inv_factorial(3),  inv_factorial(4), inv_factorial(5),  inv_factorial(6),
    inv_factorial(7),  inv_factorial(8),  inv_factorial(9), inv_factorial(10), inv_factorial(11),
    inv_factorial(12), inv_factorial(13), inv_factorial(14)};

// x = k*ln2 + r + c, where r + c is x - k*ln2 to about 2^-100 and |r| <= ln2/2 (plus 2^-40).
struct Ln2Reduction {
    int k;
    double r;
    double c;
};

Ln2Reduction reduce_by_ln2(double x) {
    const int k = bits::round_to_int(x * kInvLn2);
    const double hi = x - k * kLn2Hi; // exact
    const double lo = k * kLn2Lo;
    const double r = hi - lo;
    return {k, r, (hi - r) - lo};
}

// r^2 * (exp(r) - 1 - r) / r^2, the part of exp(r) - 1 beyond r.
double exp_beyond_linear(double r) {
    return (r * r) * bits::polynomial(kExpTail, r);
}

// exp(r + c) for |r| <= 0.35 and tiny c, in [0.7, 1.42].
double exp_reduced(double r, double c) {
    const double s = 1.0 + r;
    const double s_error = (1.0 - s) + r; // exact: |r| < 1
    return s + (s_error + (exp_beyond_linear(r) + c * (1.0 + r)));
}

struct TwoSum {
    double sum;
    double error;
};
TwoSum two_sum(double a, double b) {
    const double s = a + b;
    const double b_part = s - a;
    return {s, (a - (s - b_part)) + (b - b_part)};
}

} // namespace

double exp(double x) {
    if (bits::is_nan(x)) {
        return x + x;
    }
    if (x > kExpOverflow) {
        return bits::pow2(1023) * 2.0; // +inf
    }
    if (x < kExpUnderflow) {
        return 0.0;
    }
    if (bits::abs(x) < 0x1p-54) {
        return 1.0 + x;
    }
    const Ln2Reduction red = reduce_by_ln2(x);
    return bits::scale_by_pow2(exp_reduced(red.r, red.c), red.k);
}

double expm1(double x) {
    if (bits::is_nan(x)) {
        return x + x;
    }
    if (x > kExpOverflow) {
        return bits::pow2(1023) * 2.0; // +inf
    }
    if (x < kExpm1MinusOne) {
        return -1.0; // exp(x) < 2^-56: -1 + exp(x) rounds to -1
    }
    if (bits::abs(x) < 0x1p-54) {
        return x; // keeps -0
    }
    if (bits::abs(x) <= kHalfLn2) {
        return x + exp_beyond_linear(x);
    }
    const Ln2Reduction red = reduce_by_ln2(x);
    if (red.k < -53 || red.k > 53) {
        return bits::scale_by_pow2(exp_reduced(red.r, red.c), red.k) - 1.0;
    }
    // 2^k * (1 + r + tail) - 1 = (2^k - 1) + 2^k*r + 2^k*tail, where 2^k - 1 and the scalings
    // are exact; the first sum is kept exact, so that only the last addition rounds.
    const double scale = bits::pow2(red.k);
    const double tail = exp_beyond_linear(red.r) + red.c * (1.0 + red.r);
    const TwoSum head = two_sum(scale - 1.0, scale * red.r);
    return head.sum + (head.error + scale * tail);
}

} // namespace carrom::det
