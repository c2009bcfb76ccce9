// The exact engine against closed-form answers: free slide, stop, head-on and cut hits with
// both mass ratios, cushion bounce, pocket entry. Tolerance 1e-9 px (the target).

#include "common/physics_test_util.hpp"

#include <cmath>

namespace carrom {
namespace {

using test::coin;
using test::striker;

constexpr double kTol = 1e-9;

const PhysicsConfig kConfig;
const double kK = kConfig.damping_per_s;

// Closed form of damped free motion until the stop speed.
double travel_until_stop_px(double speed) {
    return (speed - kConfig.stop_speed_px_s) / kK;
}
double time_until_stop_s(double speed) {
    return std::log(speed / kConfig.stop_speed_px_s) / kK;
}
// Speed after travelling distance d from speed v: v - k d (since dv/dx = -k).
double speed_after_px(double v, double d) {
    return v - kK * d;
}
// Time to travel d starting at speed v.
double time_to_travel_s(double v, double d) {
    return -std::log1p(-kK * d / v) / kK;
}

const Event* find_event(const SimResult& r, EventKind kind, int a) {
    for (const Event& e : r.events) {
        if (e.kind == kind && e.a == a) {
            return &e;
        }
    }
    return nullptr;
}

TEST(ExactAnalytic, DampingRateIsTheSeedsFrictionPerFrameAt60Hz) {
    EXPECT_NEAR(kK, 0.906818, 1e-6);
    EXPECT_DOUBLE_EQ(std::exp(-kK / 60.0), 0.985);
}

TEST(ExactAnalytic, FreeSlideStopsWhereTheClosedFormSays) {
    const std::vector<Body> scene{coin(1, 200.0, 300.0, 60.0, 80.0)}; // speed 100 px/s
    const SimulateResult sim = simulate_exact(kConfig, scene);
    ASSERT_FALSE(sim.error);
    const Body& b = sim.result.bodies[0];
    const double d = travel_until_stop_px(100.0);
    EXPECT_NEAR(b.pos_px.x, 200.0 + 0.6 * d, kTol);
    EXPECT_NEAR(b.pos_px.y, 300.0 + 0.8 * d, kTol);
    EXPECT_EQ(b.vel_px_s, (Vec2{0.0, 0.0}));
    EXPECT_NEAR(sim.result.end_time_s, time_until_stop_s(100.0), 1e-12);
    ASSERT_EQ(sim.result.events.size(), 1u);
    EXPECT_EQ(sim.result.events[0].kind, EventKind::Stop);
}

TEST(ExactAnalytic, StateAtAnyTimeFollowsTheDampedMotion) {
    const std::vector<Body> scene{coin(1, 200.0, 300.0, 100.0, 0.0)};
    SimOptions options;
    options.record_trajectory = true;
    const SimulateResult sim = simulate_exact(kConfig, scene, options);
    for (double t : {0.0, 0.1, 0.5, 1.0, 2.0}) {
        const std::vector<Body> state = state_at(kConfig, sim.result.trajectory, t);
        const double expected = 200.0 + 100.0 * (1.0 - std::exp(-kK * t)) / kK;
        EXPECT_NEAR(state[0].pos_px.x, expected, kTol) << "t = " << t;
        EXPECT_NEAR(state[0].vel_px_s.x, 100.0 * std::exp(-kK * t), 1e-9) << "t = " << t;
    }
}

TEST(ExactAnalytic, UntilStopsTheSimulationAtThatTime) {
    const std::vector<Body> scene{coin(1, 200.0, 300.0, 100.0, 0.0)};
    SimOptions options;
    options.until_s = 0.5;
    const SimulateResult sim = simulate_exact(kConfig, scene, options);
    EXPECT_NEAR(sim.result.bodies[0].pos_px.x, 200.0 + 100.0 * (1.0 - std::exp(-kK * 0.5)) / kK,
                kTol);
    EXPECT_NEAR(sim.result.bodies[0].vel_px_s.x, 100.0 * std::exp(-kK * 0.5), 1e-9);
    EXPECT_DOUBLE_EQ(sim.result.end_time_s, 0.5);
}

TEST(ExactAnalytic, BodiesAtOrBelowTheStopSpeedDoNotMove) {
    for (double speed : {1e-3, 1.0, 6.0}) {
        const std::vector<Body> scene{coin(1, 300.0, 300.0, speed, 0.0)};
        const SimulateResult sim = simulate_exact(kConfig, scene);
        EXPECT_EQ(sim.result.bodies[0].pos_px, (Vec2{300.0, 300.0})) << speed;
        EXPECT_EQ(sim.result.bodies[0].vel_px_s, (Vec2{0.0, 0.0})) << speed;
    }
}

// A moving body a hits a resting body b head-on along +x; returns (a, b) final x.
struct HeadOn {
    double contact_speed;
    double va_after;
    double vb_after;
};

HeadOn head_on_expectation(double v0, double gap_px, double ma, double mb) {
    const double e = kConfig.disc_restitution;
    HeadOn h{};
    h.contact_speed = speed_after_px(v0, gap_px);
    const double j = (1.0 + e) * ma * mb / (ma + mb) * h.contact_speed;
    h.va_after = h.contact_speed - j / ma;
    h.vb_after = j / mb;
    return h;
}

TEST(ExactAnalytic, HeadOnCoinHitsCoin) {
    const std::vector<Body> scene{coin(1, 200.0, 300.0, 200.0, 0.0), coin(2, 300.0, 300.0)};
    const SimulateResult sim = simulate_exact(kConfig, scene);
    const double gap = 100.0 - 28.0;
    const HeadOn h = head_on_expectation(200.0, gap, 1.0, 1.0);
    const Event* hit = find_event(sim.result, EventKind::Collision, 1);
    ASSERT_NE(hit, nullptr);
    EXPECT_NEAR(hit->t_s, time_to_travel_s(200.0, gap), 1e-12);
    EXPECT_NEAR(hit->impulse, 1.9 * 0.5 * h.contact_speed, 1e-9);
    EXPECT_NEAR(sim.result.bodies[0].pos_px.x, 200.0 + gap + travel_until_stop_px(h.va_after),
                kTol);
    EXPECT_NEAR(sim.result.bodies[1].pos_px.x, 300.0 + travel_until_stop_px(h.vb_after), kTol);
    EXPECT_EQ(sim.result.bodies[0].pos_px.y, 300.0);
    EXPECT_EQ(sim.result.bodies[1].pos_px.y, 300.0);
}

TEST(ExactAnalytic, HeadOnStrikerHitsCoinWithMassRatioTwo) {
    const std::vector<Body> scene{striker(19, 150.0, 300.0, 200.0, 0.0), coin(2, 250.0, 300.0)};
    const SimulateResult sim = simulate_exact(kConfig, scene);
    const double gap = 100.0 - 32.0;
    const HeadOn h = head_on_expectation(200.0, gap, 2.0, 1.0);
    EXPECT_NEAR(sim.result.bodies[0].pos_px.x, 150.0 + gap + travel_until_stop_px(h.va_after),
                kTol);
    EXPECT_NEAR(sim.result.bodies[1].pos_px.x, 250.0 + travel_until_stop_px(h.vb_after), kTol);
}

TEST(ExactAnalytic, HeadOnCoinHitsStrikerWithMassRatioOneHalf) {
    const std::vector<Body> scene{coin(1, 150.0, 300.0, 300.0, 0.0), striker(19, 250.0, 300.0)};
    const SimulateResult sim = simulate_exact(kConfig, scene);
    const double gap = 100.0 - 32.0;
    const HeadOn h = head_on_expectation(300.0, gap, 1.0, 2.0);
    ASSERT_LT(h.va_after, -kConfig.stop_speed_px_s); // the coin bounces back
    EXPECT_NEAR(sim.result.bodies[0].pos_px.x, 150.0 + gap - travel_until_stop_px(-h.va_after),
                kTol);
    EXPECT_NEAR(sim.result.bodies[1].pos_px.x, 250.0 + travel_until_stop_px(h.vb_after), kTol);
}

// Body a moves along +x with b's centre offset by h = b.y - a.y; they touch when
// dx = sqrt(R^2 - h^2). The normal impulse is along the line of centres, the tangential
// velocity is kept.
void check_cut(Body a, Body b) {
    const double h = b.pos_px.y - a.pos_px.y;
    const double ma = kConfig.mass(a.kind);
    const double mb = kConfig.mass(b.kind);
    const double reach = kConfig.radius(a.kind) + kConfig.radius(b.kind);
    const double v0 = a.vel_px_s.x;
    const double dx = std::sqrt(reach * reach - h * h);
    const double travel = (b.pos_px.x - dx) - a.pos_px.x;
    const double vc = speed_after_px(v0, travel);
    const Vec2 n{dx / reach, h / reach};
    const double vn = vc * n.x;
    const double j = (1.0 + kConfig.disc_restitution) * ma * mb / (ma + mb) * vn;
    const Vec2 va{vc - j / ma * n.x, -j / ma * n.y};
    const Vec2 vb{j / mb * n.x, j / mb * n.y};
    const Vec2 contact_a{b.pos_px.x - dx, a.pos_px.y};
    const auto final_pos = [](Vec2 p, Vec2 v) {
        const double speed = length(v);
        if (speed <= kConfig.stop_speed_px_s) {
            return p;
        }
        return p + v * (travel_until_stop_px(speed) / speed);
    };
    const SimulateResult sim = simulate_exact(kConfig, std::vector<Body>{a, b});
    ASSERT_FALSE(sim.error);
    ASSERT_EQ(sim.result.stats.events, 3) << "one collision and two stops, nothing else";
    const Vec2 pa = final_pos(contact_a, va);
    const Vec2 pb = final_pos(b.pos_px, vb);
    EXPECT_NEAR(sim.result.bodies[0].pos_px.x, pa.x, kTol);
    EXPECT_NEAR(sim.result.bodies[0].pos_px.y, pa.y, kTol);
    EXPECT_NEAR(sim.result.bodies[1].pos_px.x, pb.x, kTol);
    EXPECT_NEAR(sim.result.bodies[1].pos_px.y, pb.y, kTol);
}

TEST(ExactAnalytic, CutHitCoinOnCoin) {
    check_cut(coin(1, 150.0, 310.0, 250.0, 0.0), coin(2, 250.0, 300.0));
}

TEST(ExactAnalytic, CutHitStrikerOnCoin) {
    check_cut(striker(19, 150.0, 280.0, 250.0, 0.0), coin(2, 250.0, 300.0));
}

TEST(ExactAnalytic, CutHitCoinOnStriker) {
    check_cut(coin(1, 150.0, 315.0, 300.0, 0.0), striker(19, 250.0, 300.0));
}

TEST(ExactAnalytic, CushionReversesTheNormalVelocityScaledByPointEight) {
    // Towards the right cushion (centre limit 551 px) at 45 degrees.
    const std::vector<Body> scene{coin(1, 450.0, 200.0, 300.0, 300.0)};
    const SimulateResult sim = simulate_exact(kConfig, scene);
    const double limit = kConfig.cushion_max(kConfig.coin_radius_px);
    const double to_wall = (limit - 450.0) * std::sqrt(2.0); // path length to the cushion
    const double speed0 = 300.0 * std::sqrt(2.0);
    const double vc = speed_after_px(speed0, to_wall) / std::sqrt(2.0); // per axis
    const Vec2 after{-0.8 * vc, vc};
    const double travel = travel_until_stop_px(length(after));
    const Event* bounce = find_event(sim.result, EventKind::Cushion, 1);
    ASSERT_NE(bounce, nullptr);
    EXPECT_EQ(bounce->b, kCushionRight);
    EXPECT_NEAR(bounce->t_s, time_to_travel_s(speed0, to_wall), 1e-12);
    EXPECT_NEAR(bounce->impulse, 1.8 * vc, 1e-9);
    const Vec2 expected = Vec2{limit, 200.0 + (limit - 450.0)} + after * (travel / length(after));
    EXPECT_NEAR(sim.result.bodies[0].pos_px.x, expected.x, kTol);
    EXPECT_NEAR(sim.result.bodies[0].pos_px.y, expected.y, kTol);
}

TEST(ExactAnalytic, PocketEntryIsWhenTheCentreCrossesThePocketCircle) {
    const Vec2 pocket = kConfig.pocket_centres()[3]; // bottom-right (543, 543)
    const std::vector<Body> scene{coin(1, 450.0, 450.0, 300.0, 300.0)};
    const SimulateResult sim = simulate_exact(kConfig, scene);
    const double to_entry = length(pocket - Vec2{450.0, 450.0}) - kConfig.pocket_radius_px;
    const Event* entry = find_event(sim.result, EventKind::Pocket, 1);
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(entry->b, 3);
    EXPECT_NEAR(entry->t_s, time_to_travel_s(300.0 * std::sqrt(2.0), to_entry), 1e-12);
    EXPECT_NEAR(length(entry->pos_px - pocket), kConfig.pocket_radius_px, kTol);
    EXPECT_TRUE(sim.result.bodies[0].pocketed);
    EXPECT_EQ(sim.result.stats.events, 1);
}

TEST(ExactAnalytic, EveryPocketIsReachableAlongItsDiagonal) {
    // The seed's pockets could not be reached at all; ours touch both cushions.
    const auto pockets = kConfig.pocket_centres();
    for (std::size_t p = 0; p < 4; ++p) {
        const Vec2 dir{pockets[p].x < 300.0 ? -1.0 : 1.0, pockets[p].y < 300.0 ? -1.0 : 1.0};
        const std::vector<Body> scene{
            coin(1, 300.0 + 100.0 * dir.x, 300.0 + 100.0 * dir.y, 400.0 * dir.x, 400.0 * dir.y)};
        const SimulateResult sim = simulate_exact(kConfig, scene);
        EXPECT_TRUE(sim.result.bodies[0].pocketed) << "pocket " << p;
    }
}

} // namespace
} // namespace carrom
