// det_math (carrom/det_math.hpp): exact results for known values (the correctly rounded value,
// computed with mpmath at 300 bits) and the special values of C's Annex F (0, -0, inf, nan,
// subnormals, the overflow and underflow edges).

#include "carrom/det_math.hpp"
#include "carrom/double_bits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace carrom {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 0x1.921fb54442d18p+1;

// Same bits: tells +0 from -0.
void expect_bits(double actual, double expected) {
    EXPECT_EQ(double_bits(actual), double_bits(expected)) << actual << " vs " << expected;
}

TEST(DetMathValues, ExpOfKnownArguments) {
    expect_bits(det::exp(0.0), 1.0);
    expect_bits(det::exp(-0.0), 1.0);
    expect_bits(det::exp(1.0), 0x1.5bf0a8b145769p+1);
    expect_bits(det::exp(-1.0), 0x1.78b56362cef38p-2);
    expect_bits(det::exp(10.0), 0x1.5829dcf950560p+14);
    expect_bits(det::exp(0x1.62e42fefa39efp-1), 2.0); // exp(ln 2 rounded) rounds to 2
}

TEST(DetMathValues, ExpOfSpecialArguments) {
    expect_bits(det::exp(kInf), kInf);
    expect_bits(det::exp(-kInf), 0.0);
    EXPECT_TRUE(std::isnan(det::exp(kNan)));
    expect_bits(det::exp(710.0), kInf);
    expect_bits(det::exp(-746.0), 0.0);
    expect_bits(det::exp(0x1.62e42fefa39efp+9), 0x1.fffffffffff2ap+1023); // the largest finite
    expect_bits(det::exp(-0x1.74910d52d3051p+9), 0x1p-1074);              // the smallest subnormal
    expect_bits(det::exp(-1000.0), 0.0);
    expect_bits(det::exp(1e-300), 1.0);
}

TEST(DetMathValues, Expm1OfKnownAndSpecialArguments) {
    expect_bits(det::expm1(0.0), 0.0);
    expect_bits(det::expm1(-0.0), -0.0);
    expect_bits(det::expm1(1e-10), 0x1.b7cdfd9dda4e3p-34);
    expect_bits(det::expm1(-0.5), -0x1.92e9a0720d3ecp-2);
    expect_bits(det::expm1(0x1p-1074), 0x1p-1074);
    expect_bits(det::expm1(-0x1p-1074), -0x1p-1074);
    expect_bits(det::expm1(kInf), kInf);
    expect_bits(det::expm1(-kInf), -1.0);
    expect_bits(det::expm1(-40.0), -1.0);
    expect_bits(det::expm1(710.0), kInf);
    EXPECT_TRUE(std::isnan(det::expm1(kNan)));
}

TEST(DetMathValues, LogOfKnownArguments) {
    expect_bits(det::log(1.0), 0.0);
    expect_bits(det::log(2.0), 0x1.62e42fefa39efp-1);
    expect_bits(det::log(0.5), -0x1.62e42fefa39efp-1);
    expect_bits(det::log(10.0), 0x1.26bb1bbb55516p+1);
    expect_bits(det::log(0x1.5bf0a8b145769p+1), 1.0); // log(e rounded) rounds to 1
    expect_bits(det::log(0x1p-1074), -0x1.74385446d71c3p+9);
}

TEST(DetMathValues, LogOfSpecialArguments) {
    expect_bits(det::log(0.0), -kInf);
    expect_bits(det::log(-0.0), -kInf);
    expect_bits(det::log(kInf), kInf);
    EXPECT_TRUE(std::isnan(det::log(-1.0)));
    EXPECT_TRUE(std::isnan(det::log(-kInf)));
    EXPECT_TRUE(std::isnan(det::log(kNan)));
}

TEST(DetMathValues, Log1pOfKnownAndSpecialArguments) {
    expect_bits(det::log1p(0.0), 0.0);
    expect_bits(det::log1p(-0.0), -0.0);
    expect_bits(det::log1p(1.0), 0x1.62e42fefa39efp-1);
    expect_bits(det::log1p(-0.5), -0x1.62e42fefa39efp-1);
    expect_bits(det::log1p(1e-10), 0x1.b7cdfd9d1d693p-34);
    expect_bits(det::log1p(0x1p-1074), 0x1p-1074);
    expect_bits(det::log1p(-1.0), -kInf);
    expect_bits(det::log1p(kInf), kInf);
    EXPECT_TRUE(std::isnan(det::log1p(-1.5)));
    EXPECT_TRUE(std::isnan(det::log1p(-kInf)));
    EXPECT_TRUE(std::isnan(det::log1p(kNan)));
}

TEST(DetMathValues, SinAndCosOfKnownArguments) {
    expect_bits(det::sin(0.0), 0.0);
    expect_bits(det::sin(-0.0), -0.0);
    expect_bits(det::cos(0.0), 1.0);
    expect_bits(det::cos(-0.0), 1.0);
    expect_bits(det::sin(1.0), 0x1.aed548f090ceep-1);
    expect_bits(det::cos(1.0), 0x1.14a280fb5068cp-1);
    expect_bits(det::sin(-1.0), -0x1.aed548f090ceep-1);
    expect_bits(det::cos(-1.0), 0x1.14a280fb5068cp-1);
    expect_bits(det::sin(100.0), -0x1.03425b78c4db8p-1);
    expect_bits(det::cos(100.0), 0x1.b981dbf665fdfp-1);
    expect_bits(det::sin(1e-300), 1e-300);
    expect_bits(det::cos(1e-300), 1.0);
    // pi rounded is below pi by 1.2e-16: sin is that, cos is -1.
    expect_bits(det::sin(kPi), 0x1.1a62633145c07p-53);
    expect_bits(det::cos(kPi), -1.0);
}

TEST(DetMathValues, SinAndCosOfSpecialArguments) {
    EXPECT_TRUE(std::isnan(det::sin(kInf)));
    EXPECT_TRUE(std::isnan(det::cos(-kInf)));
    EXPECT_TRUE(std::isnan(det::sin(kNan)));
    EXPECT_TRUE(std::isnan(det::cos(kNan)));
    EXPECT_TRUE(std::isnan(det::sin(1e300))); // beyond the reduction's range
}

TEST(DetMathValues, Atan2OfKnownArguments) {
    expect_bits(det::atan2(1.0, 1.0), 0x1.921fb54442d18p-1);
    expect_bits(det::atan2(1.0, -1.0), 0x1.2d97c7f3321d2p+1);
    expect_bits(det::atan2(-2.0, 3.0), -0x1.2d0ead6066395p-1);
    expect_bits(det::atan2(1.0, 0.0), 0x1.921fb54442d18p+0);
    expect_bits(det::atan2(-1.0, 0.0), -0x1.921fb54442d18p+0);
    expect_bits(det::atan2(1e-300, 1.0), 1e-300);
    expect_bits(det::atan2(1.0, -1e300), kPi);
}

TEST(DetMathValues, Atan2OfSignedZerosAndInfinities) {
    expect_bits(det::atan2(0.0, 1.0), 0.0);
    expect_bits(det::atan2(-0.0, 1.0), -0.0);
    expect_bits(det::atan2(0.0, 0.0), 0.0);
    expect_bits(det::atan2(-0.0, 0.0), -0.0);
    expect_bits(det::atan2(0.0, -0.0), kPi);
    expect_bits(det::atan2(-0.0, -0.0), -kPi);
    expect_bits(det::atan2(0.0, -1.0), kPi);
    expect_bits(det::atan2(-0.0, -1.0), -kPi);
    expect_bits(det::atan2(1.0, kInf), 0.0);
    expect_bits(det::atan2(-1.0, kInf), -0.0);
    expect_bits(det::atan2(1.0, -kInf), kPi);
    expect_bits(det::atan2(-1.0, -kInf), -kPi);
    expect_bits(det::atan2(kInf, kInf), 0x1.921fb54442d18p-1);
    expect_bits(det::atan2(-kInf, -kInf), -0x1.2d97c7f3321d2p+1);
    expect_bits(det::atan2(kInf, 5.0), 0x1.921fb54442d18p+0);
    EXPECT_TRUE(std::isnan(det::atan2(kNan, 1.0)));
    EXPECT_TRUE(std::isnan(det::atan2(1.0, kNan)));
}

} // namespace
} // namespace carrom
