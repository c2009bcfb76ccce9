// det::sin and det::cos (carrom/det_math.hpp): x = n*pi/2 + y + ylo with |y| <= pi/4 (Cody and
// Waite's reduction with pi/2 in three parts, 33 + 33 + 53 bits: n times either of the first two
// is exact for |n| < 2^20), then the Taylor series of sin to degree 19 and of cos to degree 20
// on [-pi/4, pi/4] (truncation below 2^-63 relative). docs/decisions/006-deterministic-math.md.

#include "carrom/det_math.hpp"
#include "det_bits.hpp"

namespace carrom::det {
namespace {

using bits::inv_factorial;

constexpr double kPio4 = 0x1.921fb54442d18p-1;
constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
constexpr double kPio2Part1 = 0x1.921fb54400000p+0;  // pi/2 to 33 bits
constexpr double kPio2Part2 = 0x1.0b4611a600000p-34; // the next 33 bits
constexpr double kPio2Part3 = 0x1.3198a2e037073p-69; // the next 53 bits
// Beyond it n no longer fits the reduction's integer: sin and cos return nan.
constexpr double kTrigReductionLimit = 0x1p28;
constexpr double kTrigQuietNan = __builtin_bit_cast(double, 0x7ff8000000000000ULL);

// (sin(y) - y + y^3/3!) / y^5 as a polynomial in z = y^2.
constexpr double kSinTail[] = {inv_factorial(5),   -inv_factorial(7), inv_factorial(9),
                               -inv_factorial(11), inv_factorial(13), -inv_factorial(15),
                               inv_factorial(17),  -inv_factorial(19)};
// (cos(y) - 1 + y^2/2) / y^4 as a polynomial in z = y^2.
constexpr double kCosTail[] = {inv_factorial(4),   -inv_factorial(6),  inv_factorial(8),
                               -inv_factorial(10), inv_factorial(12),  -inv_factorial(14),
                               inv_factorial(16),  -inv_factorial(18), inv_factorial(20)};

// sin(y + ylo) for |y| <= pi/4 (plus rounding) and |ylo| <= ulp(y).
double sin_reduced(double y, double ylo) {
    const double z = y * y;
    const double y_cubed = z * y;
    const double series = -inv_factorial(3) + z * bits::polynomial(kSinTail, z);
    return y + (y_cubed * series + ylo * (1.0 - 0.5 * z));
}

// cos(y + ylo) for |y| <= pi/4 (plus rounding) and |ylo| <= ulp(y). 1 - y^2/2 is kept as
// w + its exact rounding error; y^2 is split exactly into z + z_lo.
double cos_reduced(double y, double ylo) {
    const bits::TwoProduct y_squared = bits::two_product(y, y);
    const double z = y_squared.hi;
    const double half_z = 0.5 * z;
    const double w = 1.0 - half_z;
    const double w_error = (1.0 - w) - half_z;
    return w + (w_error + (z * z * bits::polynomial(kCosTail, z) - (0.5 * y_squared.lo + y * ylo)));
}

// x = quadrant*pi/2 + y + ylo (quadrant taken mod 4) for |x| < kTrigReductionLimit.
struct Pio2Reduction {
    int quadrant;
    double y;
    double ylo;
};
Pio2Reduction reduce_by_pio2(double x) {
    if (bits::abs(x) <= kPio4) {
        return {0, x, 0.0};
    }
    const int n = bits::round_to_int(x * kTwoOverPi);
    const double dn = n;
    const double r1 = x - dn * kPio2Part1; // exact for |n| < 2^20
    const double w2 = dn * kPio2Part2;     // exact for |n| < 2^20
    const double y0 = r1 - w2;             // y0 + e0 = r1 - w2 exactly (two-sum)
    const double w2_part = r1 - y0;
    const double e0 = (r1 - (y0 + w2_part)) + (w2_part - w2);
    const double lo = e0 - dn * kPio2Part3;
    const double y = y0 + lo;
    return {n & 3, y, (y0 - y) + lo};
}

} // namespace

double sin(double x) {
    if (!(bits::abs(x) < kTrigReductionLimit)) {
        return bits::is_nan(x) ? x + x : kTrigQuietNan;
    }
    if (bits::abs(x) < 0x1p-27) {
        return x; // sin(x) = x - x^3/6 rounds to x; keeps -0
    }
    const Pio2Reduction red = reduce_by_pio2(x);
    switch (red.quadrant) {
    case 0:
        return sin_reduced(red.y, red.ylo);
    case 1:
        return cos_reduced(red.y, red.ylo);
    case 2:
        return -sin_reduced(red.y, red.ylo);
    default:
        return -cos_reduced(red.y, red.ylo);
    }
}

double cos(double x) {
    if (!(bits::abs(x) < kTrigReductionLimit)) {
        return bits::is_nan(x) ? x + x : kTrigQuietNan;
    }
    if (bits::abs(x) < 0x1p-27) {
        return 1.0; // cos(x) = 1 - x^2/2 rounds to 1
    }
    const Pio2Reduction red = reduce_by_pio2(x);
    switch (red.quadrant) {
    case 0:
        return cos_reduced(red.y, red.ylo);
    case 1:
        return -sin_reduced(red.y, red.ylo);
    case 2:
        return -cos_reduced(red.y, red.ylo);
    default:
        return sin_reduced(red.y, red.ylo);
    }
}

} // namespace carrom::det
