// time_to_reach's early rejections against the plain closed-form solve they stand for: the same
// result, bit for bit, on pairs built to sit on each rejection's boundary (grazing contacts,
// contacts right at s_max, gaps from 1e-9 px to twice the reach, speeds from 1e-3 to 1e6 px/s).
// White-box: contact_time.hpp is internal to carrom_common.

#include "contact_time.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace carrom::detail {
namespace {

// The solve with no shortcut: only "not approaching" and "touching" answer early.
double plain_time_to_reach(Vec2 d, Vec2 w, double reach, double s_max) {
    const double b = dot(d, w);
    if (b >= 0.0) {
        return kNever;
    }
    const double dd = dot(d, d);
    const double touch = reach + kTouchTolerancePx;
    if (dd <= touch * touch) {
        return -b > kApproachTolerancePxS * std::sqrt(dd) ? 0.0 : kNever;
    }
    double c = dd - reach * reach;
    if (dd < 4.0 * reach * reach) {
        const double dist = std::sqrt(dd);
        c = (dist - reach) * (dist + reach);
    }
    const double a = dot(w, w);
    const double disc = b * b - a * c;
    if (disc < 0.0) {
        return kNever;
    }
    const double s = c / (-b + std::sqrt(disc));
    return s <= s_max ? s : kNever;
}

std::uint64_t bits(double x) {
    return std::bit_cast<std::uint64_t>(x);
}

// A pair of bodies apart by `gap_px` (surface to surface), approaching at `speed_px_s` with
// impact parameter (miss distance of the centres) `aim` times the reach.
struct Pair {
    Vec2 d;
    Vec2 w;
    double reach = 0.0;
};

Pair make_pair(double reach, double gap_px, double speed_px_s, double aim, double heading) {
    const double dist = reach + gap_px;
    const Vec2 d{dist * std::cos(heading), dist * std::sin(heading)};
    // w points from b back towards a (-d), turned by the angle whose sine is aim * reach / dist.
    const double sine = std::clamp(aim * reach / dist, -1.0, 1.0);
    const double turn = std::asin(sine);
    const double back = heading + std::numbers::pi + turn;
    return {d, {speed_px_s * std::cos(back), speed_px_s * std::sin(back)}, reach};
}

class ContactTimeShortcuts : public ::testing::Test {
protected:
    std::mt19937_64 rng{20261122};
    double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng); }
    double log_uniform(double lo, double hi) {
        return std::exp(uniform(std::log(lo), std::log(hi)));
    }
    double any_reach() {
        const double reaches[] = {28.0, 32.0, 36.0, uniform(1.0, 100.0)};
        return reaches[std::uniform_int_distribution<>(0, 3)(rng)];
    }
    // Impact parameter near 1 (grazing) most of the time, anything from head-on to a wide miss
    // otherwise.
    double any_aim() {
        if (uniform(0.0, 1.0) < 0.7) {
            const double offset = log_uniform(1e-17, 1e-2);
            return uniform(0.0, 1.0) < 0.5 ? 1.0 - offset : 1.0 + offset;
        }
        return uniform(0.0, 1.5);
    }
    // s_max at, just around, or far from the contact and the rejection bound c / (-2 b).
    double any_s_max(const Pair& p) {
        const double root = plain_time_to_reach(p.d, p.w, p.reach, kNever);
        const double b = dot(p.d, p.w);
        const double c = dot(p.d, p.d) - p.reach * p.reach;
        const double bound = b < 0.0 ? c / (-2.0 * b) : 1.0;
        switch (std::uniform_int_distribution<>(0, 4)(rng)) {
        case 0:
            return kNever;
        case 1:
            return root == kNever ? bound : root;
        case 2:
            return (root == kNever ? bound : root) * (1.0 + uniform(-1e-6, 1e-6));
        case 3:
            return bound / 1.000001 * (1.0 + uniform(-1e-9, 1e-9));
        default:
            return bound * log_uniform(1e-3, 1e3);
        }
    }
};

// Every result equal to the plain solve's; and each early rejection taken many times, so the
// comparison covers it (the near-touching rejections are counted as time_to_reach decides them).
TEST_F(ContactTimeShortcuts, SameResultsAsThePlainSolve) {
    int near_rejected = 0;
    int far_rejected = 0;
    int contacts = 0;
    for (int n = 0; n < 300000; ++n) {
        const double reach = any_reach();
        const double gap = log_uniform(1e-9, 1.5 * reach);
        const Pair p = make_pair(reach, gap, log_uniform(1e-3, 1e6), any_aim(), uniform(0.0, 7.0));
        const double s_max = any_s_max(p);
        const double got = time_to_reach(p.d, p.w, p.reach, s_max);
        const double want = plain_time_to_reach(p.d, p.w, p.reach, s_max);
        ASSERT_EQ(bits(got), bits(want))
            << "d=(" << p.d.x << ", " << p.d.y << ") w=(" << p.w.x << ", " << p.w.y
            << ") reach=" << p.reach << " s_max=" << s_max;
        contacts += got != kNever ? 1 : 0;
        const double b = dot(p.d, p.w);
        const double dd = dot(p.d, p.d);
        const double touch = reach + kTouchTolerancePx;
        if (b >= 0.0 || dd <= touch * touch) {
            continue;
        }
        const double rr = reach * reach;
        const double c = dd - rr;
        const double late = 2.000001 * -b * s_max;
        if (dd < 4.0 * rr) {
            const double a = dot(p.w, p.w);
            const double slack = 1e-13 * (rr + std::fabs(c));
            near_rejected += (c - slack > late ||
                              b * b - a * c + 1e-13 * (b * b + a * (rr + std::fabs(c))) < 0.0)
                                 ? 1
                                 : 0;
        } else {
            far_rejected += c > late ? 1 : 0;
        }
    }
    EXPECT_GT(near_rejected, 10000);
    EXPECT_GT(far_rejected, 1000);
    EXPECT_GT(contacts, 10000);
}

// Grazing pairs a hair either side of tangency, near touching: the discriminant's sign is
// decided by the last bits, so the near rejection must stand aside and the full solve decide.
TEST_F(ContactTimeShortcuts, GrazingNearTouchingPairsAreSolvedExactly) {
    int hits = 0;
    int misses = 0;
    for (int n = 0; n < 100000; ++n) {
        const double reach = any_reach();
        const double offset = log_uniform(1e-17, 1e-9);
        const double aim = n % 2 == 0 ? 1.0 - offset : 1.0 + offset;
        const Pair p = make_pair(reach, log_uniform(1e-6, reach), log_uniform(1.0, 1e4), aim,
                                 uniform(0.0, 7.0));
        const double got = time_to_reach(p.d, p.w, p.reach, kNever);
        ASSERT_EQ(bits(got), bits(plain_time_to_reach(p.d, p.w, p.reach, kNever)));
        (got == kNever ? misses : hits) += 1;
    }
    // Both outcomes occur: the cases straddle tangency.
    EXPECT_GT(hits, 1000);
    EXPECT_GT(misses, 1000);
}

// A few exact cases: head-on from a 1 px gap at 100 px/s meets after s = 0.01 (travel 1 px);
// with s_max just below that, no contact; moving apart, none.
TEST(ContactTime, HeadOnExactCases) {
    const Vec2 d{29.0, 0.0};
    const Vec2 w{-100.0, 0.0};
    EXPECT_DOUBLE_EQ(time_to_reach(d, w, 28.0, kNever), 0.01);
    EXPECT_EQ(time_to_reach(d, w, 28.0, 0.0099), kNever);
    EXPECT_EQ(time_to_reach(d, Vec2{100.0, 0.0}, 28.0, kNever), kNever);
    // A miss by 1 px of clearance (impact parameter 29 px > reach 28 px).
    EXPECT_EQ(time_to_reach(Vec2{40.0, 29.0}, w, 28.0, kNever), kNever);
}

} // namespace
} // namespace carrom::detail
