#pragma once
// Simultaneous impacts: every contact of one group is resolved at once, so the result does not
// depend on the order in which contacts are listed (a mirror-symmetric scene stays symmetric).
//
// Model (Poisson restitution over a compression phase, see docs/physics.md):
//   1. compression: find impulses J >= 0 with post-compression normal velocities
//      u_c = u_c- + (A J)_c >= 0 and J_c u_c = 0 (a linear complementarity problem; A is the
//      contacts' inverse effective mass matrix, positive definite for independent contacts);
//   2. restitution: the total impulse of contact c is (1 + e_c) J_c.
// With one restitution e for the whole group the kinetic energy changes by
// (e^2 - 1) |J|^2_A / 2 <= 0, so it never increases; a single contact reduces to
// J = (1 + e) m_a m_b / (m_a + m_b) v_n.

#include "carrom/vec2.hpp"

#include <span>
#include <vector>

namespace carrom::detail {

struct Contact {
    int a = -1;    // body index
    int b = -1;    // body index, or -1 for a cushion (infinite mass, at rest)
    Vec2 normal{}; // unit vector from a towards b (for a cushion: out of the board)
    double restitution = 0.0;
    double impulse = 0.0; // out: total normal impulse applied, mass * px/s, >= 0
};

// Relative normal velocity of a contact, px/s: positive when separating.
double normal_velocity(const Contact& c, std::span<const Vec2> vel);

// Resolves one group of contacts simultaneously: updates vel of the bodies involved and fills
// each contact's impulse. inv_mass[i] == 0 makes body i immovable. If the per-contact
// restitutions would raise the group's kinetic energy, the group is solved again with the
// smallest restitution of the group for all its contacts (which provably cannot).
class ContactSolver {
public:
    void resolve(std::span<Contact> contacts, std::span<Vec2> vel,
                 std::span<const double> inv_mass);

private:
    // Compression impulses J for the contacts (Murty's least-index principal pivoting, finite
    // for the positive definite A here); result in compression_.
    void solve_compression(std::span<const Contact> contacts, std::span<const Vec2> vel,
                           std::span<const double> inv_mass);
    void apply(std::span<Contact> contacts, std::span<Vec2> vel, std::span<const double> inv_mass,
               bool uniform_restitution, double uniform_e);

    std::vector<double> matrix_;      // A, m x m, row-major
    std::vector<double> rhs_;         // u- (pre-impact normal velocities)
    std::vector<double> compression_; // J
    std::vector<double> residual_;    // w = A J + u-
    std::vector<char> active_;
    std::vector<double> lu_; // scratch for the dense solves
    std::vector<int> index_;
    std::vector<Vec2> saved_vel_;
};

} // namespace carrom::detail
