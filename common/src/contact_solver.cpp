#include "contact_solver.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::detail {

namespace {

// Sign of body `body` in contact c: the impulse pushes a along -normal and b along +normal.
double side(const Contact& c, int body) {
    if (body == c.a) {
        return -1.0;
    }
    if (body == c.b) {
        return 1.0;
    }
    return 0.0;
}

double coupling(const Contact& c, const Contact& d, std::span<const double> inv_mass) {
    double sum = 0.0;
    for (int body : {c.a, c.b}) {
        if (body < 0) {
            continue;
        }
        const double sd = side(d, body);
        if (sd != 0.0) {
            sum += side(c, body) * sd * inv_mass[static_cast<std::size_t>(body)];
        }
    }
    return sum * dot(c.normal, d.normal);
}

// Solves the dense n x n system m x = rhs in place (x returned in rhs) with partial pivoting.
void solve_dense(std::vector<double>& m, std::vector<double>& rhs, std::size_t n) {
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t pivot = col;
        for (std::size_t row = col + 1; row < n; ++row) {
            if (std::fabs(m[row * n + col]) > std::fabs(m[pivot * n + col])) {
                pivot = row;
            }
        }
        if (pivot != col) {
            for (std::size_t k = 0; k < n; ++k) {
                std::swap(m[col * n + k], m[pivot * n + k]);
            }
            std::swap(rhs[col], rhs[pivot]);
        }
        const double diag = m[col * n + col];
        if (diag == 0.0) {
            continue; // singular direction: leave that unknown at zero
        }
        for (std::size_t row = col + 1; row < n; ++row) {
            const double f = m[row * n + col] / diag;
            if (f == 0.0) {
                continue;
            }
            for (std::size_t k = col; k < n; ++k) {
                m[row * n + k] -= f * m[col * n + k];
            }
            rhs[row] -= f * rhs[col];
        }
    }
    for (std::size_t row = n; row-- > 0;) {
        double sum = rhs[row];
        for (std::size_t k = row + 1; k < n; ++k) {
            sum -= m[row * n + k] * rhs[k];
        }
        const double diag = m[row * n + row];
        rhs[row] = diag == 0.0 ? 0.0 : sum / diag;
    }
}

} // namespace

double normal_velocity(const Contact& c, std::span<const Vec2> vel) {
    const Vec2 vb = c.b >= 0 ? vel[static_cast<std::size_t>(c.b)] : Vec2{};
    return dot(vb - vel[static_cast<std::size_t>(c.a)], c.normal);
}

void ContactSolver::solve_compression(std::span<const Contact> contacts, std::span<const Vec2> vel,
                                      std::span<const double> inv_mass) {
    const std::size_t m = contacts.size();
    matrix_.assign(m * m, 0.0);
    rhs_.resize(m);
    compression_.assign(m, 0.0);
    residual_.resize(m);
    active_.assign(m, 0);
    double scale = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
        rhs_[i] = normal_velocity(contacts[i], vel);
        scale = std::max(scale, std::fabs(rhs_[i]));
        for (std::size_t j = 0; j < m; ++j) {
            matrix_[i * m + j] = coupling(contacts[i], contacts[j], inv_mass);
        }
        // A tiny relative regularisation keeps A positive definite when contacts are
        // linearly dependent (e.g. a closed ring of touching discs).
        matrix_[i * m + i] *= 1.0 + 1e-12;
    }
    const double tolerance = 1e-13 * scale;
    // Murty's least-index principal pivoting. Terminates for P-matrices; the iteration cap is
    // only a guard against rounding in degenerate groups.
    const std::size_t max_pivots = 4 * m * m + 16;
    for (std::size_t pivot = 0; pivot < max_pivots; ++pivot) {
        index_.clear();
        for (std::size_t i = 0; i < m; ++i) {
            if (active_[i]) {
                index_.push_back(static_cast<int>(i));
            }
        }
        const std::size_t n = index_.size();
        lu_.resize(n * n);
        std::vector<double>& x = residual_; // reuse as the sub-system right-hand side
        x.assign(n, 0.0);
        for (std::size_t r = 0; r < n; ++r) {
            const auto ir = static_cast<std::size_t>(index_[r]);
            x[r] = -rhs_[ir];
            for (std::size_t c = 0; c < n; ++c) {
                lu_[r * n + c] = matrix_[ir * m + static_cast<std::size_t>(index_[c])];
            }
        }
        solve_dense(lu_, x, n);
        std::fill(compression_.begin(), compression_.end(), 0.0);
        for (std::size_t r = 0; r < n; ++r) {
            compression_[static_cast<std::size_t>(index_[r])] = x[r];
        }
        std::size_t violated = m;
        for (std::size_t i = 0; i < m && violated == m; ++i) {
            if (active_[i]) {
                if (compression_[i] < -tolerance) {
                    violated = i;
                }
                continue;
            }
            double w = rhs_[i];
            for (std::size_t j = 0; j < m; ++j) {
                w += matrix_[i * m + j] * compression_[j];
            }
            if (w < -tolerance) {
                violated = i;
            }
        }
        if (violated == m) {
            break;
        }
        active_[violated] = static_cast<char>(!active_[violated]);
    }
    for (double& j : compression_) {
        j = std::max(j, 0.0);
    }
}

void ContactSolver::apply(std::span<Contact> contacts, std::span<Vec2> vel,
                          std::span<const double> inv_mass, bool uniform_restitution,
                          double uniform_e) {
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        Contact& c = contacts[i];
        const double e = uniform_restitution ? uniform_e : c.restitution;
        c.impulse = (1.0 + e) * compression_[i];
        const Vec2 dp = c.normal * c.impulse;
        vel[static_cast<std::size_t>(c.a)] -= dp * inv_mass[static_cast<std::size_t>(c.a)];
        if (c.b >= 0) {
            vel[static_cast<std::size_t>(c.b)] += dp * inv_mass[static_cast<std::size_t>(c.b)];
        }
    }
}

void ContactSolver::resolve(std::span<Contact> contacts, std::span<Vec2> vel,
                            std::span<const double> inv_mass) {
    if (contacts.empty()) {
        return;
    }
    if (contacts.size() == 1) {
        // One contact: J = -u / (1/m_a + 1/m_b), the closed form of the general solve below.
        Contact& c = contacts[0];
        const double inv_a = inv_mass[static_cast<std::size_t>(c.a)];
        const double inv_b = c.b >= 0 ? inv_mass[static_cast<std::size_t>(c.b)] : 0.0;
        const double u = normal_velocity(c, vel);
        const double compression = inv_a + inv_b > 0.0 && u < 0.0 ? -u / (inv_a + inv_b) : 0.0;
        // The same arithmetic as apply() with this one compression impulse.
        c.impulse = (1.0 + c.restitution) * compression;
        const Vec2 dp = c.normal * c.impulse;
        vel[static_cast<std::size_t>(c.a)] -= dp * inv_a;
        if (c.b >= 0) {
            vel[static_cast<std::size_t>(c.b)] += dp * inv_b;
        }
        return;
    }
    solve_compression(contacts, vel, inv_mass);
    double e_min = contacts[0].restitution;
    bool mixed = false;
    for (const Contact& c : contacts) {
        mixed = mixed || c.restitution != e_min;
        e_min = std::min(e_min, c.restitution);
    }
    if (!mixed) {
        apply(contacts, vel, inv_mass, true, e_min);
        return;
    }
    // Mixed restitutions: keep the per-contact values unless they would add energy.
    index_.clear();
    for (const Contact& c : contacts) {
        for (int body : {c.a, c.b}) {
            if (body >= 0 && std::find(index_.begin(), index_.end(), body) == index_.end()) {
                index_.push_back(body);
            }
        }
    }
    auto energy = [&] {
        double sum = 0.0;
        for (int body : index_) {
            const auto i = static_cast<std::size_t>(body);
            if (inv_mass[i] > 0.0) {
                sum += length_squared(vel[i]) / inv_mass[i];
            }
        }
        return sum;
    };
    saved_vel_.clear();
    for (int body : index_) {
        saved_vel_.push_back(vel[static_cast<std::size_t>(body)]);
    }
    const double before = energy();
    apply(contacts, vel, inv_mass, false, 0.0);
    if (energy() <= before) {
        return;
    }
    for (std::size_t i = 0; i < index_.size(); ++i) {
        vel[static_cast<std::size_t>(index_[i])] = saved_vel_[i];
    }
    apply(contacts, vel, inv_mass, true, e_min);
}

} // namespace carrom::detail
