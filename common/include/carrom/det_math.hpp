#pragma once
// The engine's elementary functions: exp, expm1, log, log1p, sin, cos and atan2 computed with
// +, -, *, / and bit manipulation of doubles only, so that every build (any x86-64 or ARM CPU,
// any libm, WebAssembly in the page) returns the same bits for the same argument. Compiled with
// -ffp-contract=off (common/CMakeLists.txt, wasm/CMakeLists.txt): no a*b+c is fused.
//
// Accuracy: at most 1 ulp from glibc's result (itself within about half an ulp of the exact
// value) over the ranges tests/common/det_math_glibc_test.cpp draws from, sin and cos for
// |x| <= kTrigExactBound. Special values (0, -0, inf, nan) follow C's Annex F
// (tests/common/det_math_values_test.cpp).
// docs/decisions/006-deterministic-math.md gives the reasons and the methods.

namespace carrom::det {

// sin and cos reduce x by multiples of pi/2 with a three-part pi/2 whose first two parts times
// any integer below 2^20 are exact: accurate for |x| <= kTrigExactBound (radians); beyond it the
// results stay deterministic but lose accuracy, and beyond 2^28 they are nan. The engine's
// angles are below 10.
inline constexpr double kTrigExactBound = 1.0e6;

double exp(double x);
double expm1(double x);           // exp(x) - 1, accurate near 0
double log(double x);             // natural logarithm
double log1p(double x);           // log(1 + x), accurate near 0
double sin(double x);             // x in radians
double cos(double x);             // x in radians
double atan2(double y, double x); // in [-pi, pi], radians

} // namespace carrom::det
