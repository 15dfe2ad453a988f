#pragma once
// BDF2 on the scalar oscillator u'' = −ω²u as textbooks write it, in (u, v),
// independent of the incremental-potential form of time/bdf2.cpp.
#include <Eigen/Dense>

#include <vector>

namespace sinew::test {

/// uₙ, n = 0 … steps, from u₀ = 0, v₀ = V; the first step implicit Euler,
/// each step's 2×2 linear system solved directly.
inline std::vector<double> bdf2_recurrence(double omega, double h, double V, int steps)
{
    std::vector<double> u{0.0}, v{V};
    // implicit Euler: u₁ = u₀ + h v₁, v₁ = v₀ − hω² u₁
    const double u1 = (u[0] + h * v[0]) / (1.0 + h * h * omega * omega);
    u.push_back(u1);
    v.push_back(v[0] - h * omega * omega * u1);
    for (int n = 1; n < steps; ++n) {
        // u = 4/3 uₙ − 1/3 uₙ₋₁ + 2/3 h v,  v = 4/3 vₙ − 1/3 vₙ₋₁ − 2/3 h ω² u
        Eigen::Matrix2d A;
        A << 1.0, -2.0 / 3.0 * h, 2.0 / 3.0 * h * omega * omega, 1.0;
        const Eigen::Vector2d b(4.0 / 3.0 * u[n] - 1.0 / 3.0 * u[n - 1], 4.0 / 3.0 * v[n] - 1.0 / 3.0 * v[n - 1]);
        const Eigen::Vector2d next = A.partialPivLu().solve(b);
        u.push_back(next[0]);
        v.push_back(next[1]);
    }
    return u;
}

} // namespace sinew::test
