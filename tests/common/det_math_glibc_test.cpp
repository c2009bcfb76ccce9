// det_math (carrom/det_math.hpp) against glibc (the platform's std:: functions, within half an
// ulp of the exact value): at most 1 ulp apart over 4,000 arguments per function and range, drawn
// from a fixed seed, in the engine's ranges (damping factors, hazard logs, shot angles) and wider.

#include "carrom/det_math.hpp"
#include "carrom/double_bits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <random>

namespace carrom {
namespace {

// Distance in representable doubles between two finite doubles.
std::uint64_t ulp_distance(double a, double b) {
    const auto ordered = [](double x) {
        const std::uint64_t word = double_bits(x);
        return (word >> 63) != 0 ? 0x8000000000000000ULL - (word & 0x7fffffffffffffffULL)
                                 : 0x8000000000000000ULL + word;
    };
    const std::uint64_t oa = ordered(a);
    const std::uint64_t ob = ordered(b);
    return oa > ob ? oa - ob : ob - oa;
}

// The largest ulp distance between det and glibc over `count` uniform arguments in [low, high].
std::uint64_t max_ulps(const std::function<double(double)>& det_f,
                       const std::function<double(double)>& libm_f, double low, double high) {
    std::mt19937_64 random(20261128);
    std::uniform_real_distribution<double> argument(low, high);
    std::uint64_t worst = 0;
    for (int i = 0; i < 4000; ++i) {
        const double x = argument(random);
        const std::uint64_t d = ulp_distance(det_f(x), libm_f(x));
        worst = d > worst ? d : worst;
    }
    return worst;
}

// As max_ulps, x = 2^e with e uniform in [low_exponent, high_exponent].
std::uint64_t max_ulps_log_uniform(const std::function<double(double)>& det_f,
                                   const std::function<double(double)>& libm_f, double low_exponent,
                                   double high_exponent) {
    return max_ulps([&](double e) { return det_f(std::exp2(e)); },
                    [&](double e) { return libm_f(std::exp2(e)); }, low_exponent, high_exponent);
}

// glibc's functions (the standard library's are not addressable).
const auto libm_exp = [](double x) { return std::exp(x); };
const auto libm_expm1 = [](double x) { return std::expm1(x); };
const auto libm_log = [](double x) { return std::log(x); };
const auto libm_log1p = [](double x) { return std::log1p(x); };
const auto libm_sin = [](double x) { return std::sin(x); };
const auto libm_cos = [](double x) { return std::cos(x); };

TEST(DetMathGlibc, ExpWithinOneUlp) {
    EXPECT_LE(max_ulps(det::exp, libm_exp, -2.0, 0.0), 1u); // damping factors exp(-k*dt)
    EXPECT_LE(max_ulps(det::exp, libm_exp, -50.0, 50.0), 1u);
    EXPECT_LE(max_ulps(det::exp, libm_exp, -708.0, 709.0), 1u);
}

TEST(DetMathGlibc, Expm1WithinOneUlp) {
    EXPECT_LE(max_ulps(det::expm1, libm_expm1, -1.0, 0.0), 1u); // trajectory's -expm1(-k*t)
    EXPECT_LE(max_ulps(det::expm1, libm_expm1, -0.001, 0.001), 1u);
    EXPECT_LE(max_ulps(det::expm1, libm_expm1, -40.0, 40.0), 1u);
    EXPECT_LE(max_ulps(det::expm1, libm_expm1, 30.0, 709.0), 1u);
}

TEST(DetMathGlibc, LogWithinOneUlp) {
    EXPECT_LE(max_ulps(det::log, libm_log, 0.0, 1.0), 1u); // hazard draws -log(u)
    EXPECT_LE(max_ulps(det::log, libm_log, 0.5, 2.0), 1u);
    EXPECT_LE(max_ulps_log_uniform(det::log, libm_log, -1074.0, 1023.0), 1u);
}

TEST(DetMathGlibc, Log1pWithinOneUlp) {
    EXPECT_LE(max_ulps(det::log1p, libm_log1p, -1.0, 0.0), 1u); // event queue's log1p(-x)
    EXPECT_LE(max_ulps(det::log1p, libm_log1p, -1e-6, 1e-6), 1u);
    EXPECT_LE(max_ulps(det::log1p, libm_log1p, -1.0, 100.0), 1u);
    EXPECT_LE(max_ulps_log_uniform(det::log1p, libm_log1p, -60.0, 1000.0), 1u);
}

TEST(DetMathGlibc, SinAndCosWithinOneUlp) {
    EXPECT_LE(max_ulps(det::sin, libm_sin, -7.0, 7.0), 1u); // shot and scene angles
    EXPECT_LE(max_ulps(det::cos, libm_cos, -7.0, 7.0), 1u);
    EXPECT_LE(max_ulps(det::sin, libm_sin, -1e-3, 1e-3), 1u);
    EXPECT_LE(max_ulps(det::cos, libm_cos, -1e-3, 1e-3), 1u);
    EXPECT_LE(max_ulps(det::sin, libm_sin, -det::kTrigExactBound, det::kTrigExactBound), 1u);
    EXPECT_LE(max_ulps(det::cos, libm_cos, -det::kTrigExactBound, det::kTrigExactBound), 1u);
}

TEST(DetMathGlibc, Atan2WithinOneUlp) {
    std::mt19937_64 random(20261128);
    std::uniform_real_distribution<double> coordinate(-1000.0, 1000.0); // board offsets, px
    std::uniform_real_distribution<double> exponent(-300.0, 300.0);
    std::uint64_t worst = 0;
    for (int i = 0; i < 8000; ++i) {
        double y = coordinate(random);
        double x = coordinate(random);
        if (i % 2 == 1) { // any magnitudes
            y *= std::exp2(exponent(random));
            x *= std::exp2(exponent(random));
        }
        const std::uint64_t d = ulp_distance(det::atan2(y, x), std::atan2(y, x));
        worst = d > worst ? d : worst;
    }
    EXPECT_LE(worst, 1u);
}

} // namespace
} // namespace carrom
