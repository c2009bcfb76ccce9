// det::atan2 (carrom/det_math.hpp): t = |y/x| with the division's exact remainder, atan(t) from
// the Taylor series on [0, 7/16) (degree 47, truncation below 2^-60 relative), from
// atan(c) + atan((t - c) / (1 + t*c)) with c = i/8 (a table of atan(c) in two parts) on
// [7/16, 2.5], and from pi/2 - atan(1/t) beyond; then the quadrant from the signs.
// docs/decisions/006-deterministic-math.md.

#include "carrom/det_math.hpp"
#include "det_bits.hpp"

namespace carrom::det {
namespace {

constexpr double kPiHi = 0x1.921fb54442d18p+1;
constexpr double kPiLo = 0x1.1a62633145c07p-53;
constexpr double kPio2Hi = 0x1.921fb54442d18p+0;
constexpr double kPio2Lo = 0x1.1a62633145c07p-54;
constexpr double kPio4Hi = 0x1.921fb54442d18p-1;
constexpr double kThreePio4Hi = 0x1.2d97c7f3321d2p+1;
constexpr double kAtanInfinity = __builtin_bit_cast(double, 0x7ff0000000000000ULL);

// (atan(t) - t) / t^3 = -1/3 + z/5 - z^2/7 + ... - z^22/47, z = t^2.
constexpr double kAtanTail[] = {-1.0 / 3.0,  1.0 / 5.0,   -1.0 / 7.0,  1.0 / 9.0,   -1.0 / 11.0,
                                1.0 / 13.0,  -1.0 / 15.0, 1.0 / 17.0,  -1.0 / 19.0, 1.0 / 21.0,
                                -1.0 / 23.0, 1.0 / 25.0,  -1.0 / 27.0, 1.0 / 29.0,  -1.0 / 31.0,
                                1.0 / 33.0,  -1.0 / 35.0, 1.0 / 37.0,  -1.0 / 39.0, 1.0 / 41.0,
                                -1.0 / 43.0, 1.0 / 45.0,  -1.0 / 47.0};

// atan(i/8) = hi + lo for i = 0..20, hi rounded to nearest, lo the rest rounded to nearest.
struct AtanPoint {
    double hi;
    double lo;
};
constexpr AtanPoint kAtanTable[] = {
    {0.0, 0.0},
    {0x1.fd5ba9aac2f6ep-4, -0x1.cd37686760c17p-59},
    {0x1.f5b75f92c80ddp-3, 0x1.8ab6e3cf7afbdp-57},
    {0x1.6f61941e4def1p-2, -0x1.c63aae6f6e918p-56},
    {0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56},
    {0x1.1e00babdefeb4p-1, -0x1.928df287a668fp-58},
    {0x1.4978fa3269ee1p-1, 0x1.2419a87f2a458p-56},
    {0x1.700a7c5784634p-1, -0x1.8c34d25aadef6p-56},
    {0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55},
    {0x1.b034f38649c88p-1, -0x1.be88d6936f833p-55},
    {0x1.cac7c57846f9ep-1, 0x1.0dae13ad18a6bp-55},
    {0x1.e24dd44c855d1p-1, 0x1.f7ac612ab33d8p-55},
    {0x1.f730bd281f69bp-1, 0x1.007887af0cbbdp-56},
    {0x1.04e67277a01d7p+0, 0x1.7115496c13eb6p-57},
    {0x1.0d38f2c5ba09fp+0, -0x1.bd0dc231bfd70p-54},
    {0x1.14b1dd5f90ce1p+0, -0x1.212d570a63fa2p-56},
    {0x1.1b6e192ebbe44p+0, 0x1.b1b466a88828ep-54},
    {0x1.21862f3fade36p+0, 0x1.4887628d68748p-54},
    {0x1.270ef55a53a25p+0, -0x1.a66b1af5f84fbp-54},
    {0x1.2c1a241d66dc3p+0, 0x1.82b2d58b6a8e9p-54},
    {0x1.30b6d796a4da8p+0, 0x1.6254cb03bb199p-54},
};

// atan(t) for |t| < 7/16, split as t + tail.
double atan_series_tail(double t) {
    const double z = t * t;
    return (z * t) * bits::polynomial(kAtanTail, z);
}

// atan(t + t_lo) for t >= 0 (t may be +inf) and |t_lo| <= ulp(t).
double atan_nonnegative(double t, double t_lo) {
    if (t < 0x1p-27) {
        return t + t_lo;
    }
    if (t < 0.4375) {
        return t + (atan_series_tail(t) + t_lo / (1.0 + t * t));
    }
    if (t <= 2.5) {
        const int i = bits::round_to_int(8.0 * t);
        const double c = i * 0.125;
        // t - c is exact (Sterbenz: c/2 <= t <= 2c); d = atan(t + t_lo) - atan(c) reduced.
        const double d = ((t - c) + t_lo) / (1.0 + t * c);
        return kAtanTable[i].hi + ((d + atan_series_tail(d)) + kAtanTable[i].lo);
    }
    if (t > 0x1p60) {
        return kPio2Hi + kPio2Lo;
    }
    // atan(t) = pi/2 - atan(1/t), 1/t < 0.4.
    const double inv = 1.0 / t;
    const double inv_lo = -inv * (t_lo / t);
    return kPio2Hi - ((inv + (atan_series_tail(inv) + inv_lo)) - kPio2Lo);
}

} // namespace

double atan2(double y, double x) {
    if (bits::is_nan(x) || bits::is_nan(y)) {
        return x + y;
    }
    const bool x_negative = bits::sign_bit(x);
    const double ay = bits::abs(y);
    const double ax = bits::abs(x);
    if (ay == 0.0) { // atan2(+-0, x): +-0 for x >= +0, +-pi for x <= -0
        return x_negative ? bits::copy_sign(kPiHi + kPiLo, y) : y;
    }
    if (ax == kAtanInfinity) {
        if (ay == kAtanInfinity) {
            return bits::copy_sign(x_negative ? kThreePio4Hi : kPio4Hi, y);
        }
        return x_negative ? bits::copy_sign(kPiHi + kPiLo, y) : bits::copy_sign(0.0, y);
    }
    if (ax == 0.0 || ay == kAtanInfinity) {
        return bits::copy_sign(kPio2Hi + kPio2Lo, y);
    }
    const double t = ay / ax;
    double t_lo = 0.0;
    const int ex = bits::biased_exponent(ax);
    const int ey = bits::biased_exponent(ay);
    if (ex > 100 && ex < 1900 && ey > 100 && ey < 1900 && t < 0x1p800 && t > 0x1p-800) {
        // ay = t*ax + remainder exactly; t_lo = remainder / ax.
        const bits::TwoProduct p = bits::two_product(t, ax);
        t_lo = ((ay - p.hi) - p.lo) / ax;
    }
    const double a = atan_nonnegative(t, t_lo);
    return bits::copy_sign(x_negative ? kPiHi - (a - kPiLo) : a, y);
}

} // namespace carrom::det
