// The contact solver's regularisation, measured against the closed form (docs/physics.md,
// "Regularisation bias of the contact solver"): a group of two or more contacts is solved with
// A's diagonal scaled by 1 + 1e-12, a single contact exactly. White-box: contact_solver.hpp is
// internal to carrom_common.

#include "contact_solver.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace carrom::detail {
namespace {

constexpr double kInvStriker = 0.5;
constexpr double kInvCoin = 1.0;
constexpr double kE = 0.5;

// The striker (body 0) moving up at 100 px/s into two coins (bodies 1, 2) touching it
// symmetrically: normal velocity -80 px/s on each contact, n1 . n2 = 0.28.
TEST(ContactSolverBias, TwoContactGroupIsBiasedByTheDocumentedAmount) {
    std::vector<Contact> contacts{{0, 1, {0.6, -0.8}, kE, 0.0}, {0, 2, {-0.6, -0.8}, kE, 0.0}};
    std::vector<Vec2> vel{{0.0, -100.0}, {0.0, 0.0}, {0.0, 0.0}};
    const std::vector<double> inv_mass{kInvStriker, kInvCoin, kInvCoin};
    ContactSolver solver;
    solver.resolve(contacts, vel, inv_mass);
    const double coupling = 0.28 * kInvStriker;
    const double diagonal = kInvStriker + kInvCoin;
    const double exact = (1.0 + kE) * 80.0 / (diagonal + coupling);
    const double regularised = (1.0 + kE) * 80.0 / (diagonal * (1.0 + 1e-12) + coupling);
    for (const Contact& c : contacts) {
        EXPECT_NEAR(c.impulse / regularised - 1.0, 0.0, 1e-15);
        // Relative bias 1e-12 * diagonal / (diagonal + coupling) = 9.1e-13, below the exact value.
        EXPECT_NEAR(c.impulse / exact - 1.0, -1e-12 * diagonal / (diagonal + coupling), 1e-14);
    }
}

TEST(ContactSolverBias, SingleContactIsExact) {
    std::vector<Contact> contacts{{0, 1, {0.0, -1.0}, kE, 0.0}};
    std::vector<Vec2> vel{{0.0, -100.0}, {0.0, 0.0}};
    const std::vector<double> inv_mass{kInvStriker, kInvCoin};
    ContactSolver solver;
    solver.resolve(contacts, vel, inv_mass);
    EXPECT_EQ(contacts[0].impulse, (1.0 + kE) * 100.0 / (kInvStriker + kInvCoin));
}

} // namespace
} // namespace carrom::detail
