#pragma once
// The engine's elementary functions: exp, expm1, log, log1p, sin, cos and atan2 computed with
// +, -, *, / and bit manipulation of doubles only, so that every build (any x86-64 or ARM CPU,
// any libm, WebAssembly in the page) returns the same bits for the same argument. Compiled with
// -ffp-contract=off (common/CMakeLists.txt, wasm/CMakeLists.txt): no a*b+c is fused.
//
// Accuracy: within 1 ulp of the exact value for every finite argument of exp, expm1, log, log1p
// and atan2, and for sin and cos with |x| <= kTrigExactBound; tests/common/det_math_test.cpp
// checks agreement with glibc. Special values (0, -0, inf, nan) follow C's Annex F.
// docs/decisions/006-deterministic-math.md gives the reasons and the methods.

namespace carrom::det {

// sin and cos reduce x by multiples of pi/2 with a three-part pi/2 whose first two parts times
// any integer below 2^20 are exact: within 1 ulp for |x| <= kTrigExactBound (radians); beyond
// it the results stay deterministic but lose accuracy. The engine's angles are below 10.
inline constexpr double kTrigExactBound = 1.0e6;

double exp(double x);
double expm1(double x);           // exp(x) - 1, exact near 0
double log(double x);             // natural logarithm
double log1p(double x);           // log(1 + x), exact near 0
double sin(double x);             // x in radians
double cos(double x);             // x in radians
double atan2(double y, double x); // in [-pi, pi], radians

} // namespace carrom::det
