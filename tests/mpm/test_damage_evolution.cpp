// AnisoMPM's damage evolution on the grid (seed 004 Alg. 3–10, §2; issue
// 34): the phase-field profile, explicit and implicit updates against the
// local law, irreversibility and the damage threshold.
#include "sinew/energies/models/qr_anisotropic.hpp"
#include "sinew/mpm/damage/driving_force.hpp"
#include "sinew/mpm/damage/explicit_damage.hpp"
#include "sinew/mpm/damage/implicit_damage.hpp"
#include "sinew/runs/jacobi_cg.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>
#include <vector>

using namespace sinew;

namespace {

/// Jacobi-preconditioned CG (runs/, solvers/) to relative residual `tolerance`.
SpdSolve cg_solve(double tolerance) { return jacobi_cg(tolerance, 100000); }

/// A 2D block of particles, 2 × 2 per cell of dx over cells [i0, i1) × [0, rows),
/// F = `F`, with `field` as every particle's phase-field point.
Particles<2> particle_block(double dx, int i0, int i1, int rows, const Eigen::Matrix2d& F, const PhaseFieldPoint<2>& field)
{
    Particles<2> particles;
    const double volume = 0.25 * dx * dx;
    for (int i = i0; i < i1; ++i)
        for (int j = 0; j < rows; ++j)
            for (const double a : {0.25, 0.75})
                for (const double b : {0.25, 0.75})
                    particles.add(Eigen::Vector2d((i + a) * dx, (j + b) * dx), Eigen::Vector2d::Zero(), volume, volume);
    for (auto& f : particles.F)
        f = F;
    particles.phase_field.assign(particles.F.size(), field);
    return particles;
}

QrAnisotropic<2> disk_material() { return QrAnisotropic<2>({{"mu", 40.0}, {"lambda", 80.0}}); }

/// The largest |d(x_i) − d_exact(x_i)| at the nodes with |x_i| ≤ 5 l₀ of the
/// steady field with a crack at x = 0 held at d = 1, on a strip [−L, L] with
/// L = 10 l₀; d_exact(x) = cosh((L − |x|)/l₀)/cosh(L/l₀), exp(−|x|/l₀) to
/// e^{−10} there. The crack: the nodes at |x| ≤ dx held at 1, so that the
/// cubic spline's field Σ_j N_j(x) d_j is 1 at x = 0 (the spline does not
/// interpolate its coefficients); d(x_i) = (d_{i−1} + 4d_i + d_{i+1})/6 along
/// x (the field is uniform in y).
double profile_error(double l0, double dx)
{
    const int half = static_cast<int>(std::lround(10.0 * l0 / dx));
    PhaseFieldPoint<2> field;
    field.l0 = l0;
    const Particles<2> particles = particle_block(dx, -half, half, 4, Eigen::Matrix2d::Identity(), field);
    DamageGrid<2> grid(dx);
    damage_to_grid(particles, grid);
    // τ = Δt/η = 10¹⁰ and dⁿ = 0, D̃ = 0: (A + B) d = c is d − l₀²Δd = O(1/τ).
    const DamageSystem<2> system(particles, std::vector<double>(particles.F.size(), 0.0), 1e10, grid);
    std::vector<int> crack;
    for (int slot = 0; slot < grid.nodes.slots(); ++slot)
        if (std::abs(grid.nodes.node(slot)[0]) <= 1 && grid.weight[static_cast<std::size_t>(slot)] > 0.0)
            crack.push_back(slot);
    SpdSolveOutcome outcome;
    const Eigen::VectorXd d =
        solve_damage_system(system, grid, crack, DamagePreconditioner::full_diagonal, cg_solve(1e-13), outcome);
    REQUIRE(outcome.converged);
    std::map<int, double> row;  // d_i along x at the node row y = 2 dx
    for (int slot = 0; slot < grid.nodes.slots(); ++slot)
        if (grid.nodes.node(slot)[1] == 2)
            row[grid.nodes.node(slot)[0]] = d[slot];
    const double L = half * dx;
    double error = 0.0;
    for (const auto& [i, coefficient] : row) {
        const double x = std::abs(i * dx);
        if (x > 5.0 * l0)
            continue;
        const double value = (row.at(i - 1) + 4.0 * coefficient + row.at(i + 1)) / 6.0;
        error = std::max(error, std::abs(value - std::cosh((L - x) / l0) / std::cosh(L / l0)));
    }
    return error;
}

/// d(t) of ηḋ = (1 − d)D̃ − d from d = 0 at constant D̃ (a uniform field: Δd = 0).
double local_law(double D, double eta, double t) { return D / (1.0 + D) * (1.0 - std::exp(-(1.0 + D) * t / eta)); }

} // namespace

TEST_CASE("damage: with a crack held at d = 1 the steady implicit field is exp(-|x|/l0) and converges with dx",
          "[mpm][damage]")
{
    // The largest error sits next to the crack, where exp(−|x|/l₀) has its
    // kink: first order in dx/l₀ is what a smooth spline can do there
    // (measured: 0.168, 0.089, 0.046, 0.023 at l₀/dx = 4, 8, 16, 32).
    const double l0 = 0.04;
    std::vector<double> errors;
    for (const int cells_per_l0 : {4, 8, 16, 32}) {
        errors.push_back(profile_error(l0, l0 / cells_per_l0));
        CAPTURE(cells_per_l0, errors.back());
        CHECK(errors.back() < 1.0 / cells_per_l0);
    }
    for (std::size_t k = 2; k < errors.size(); ++k) {
        const double order = std::log2(errors[k - 1] / errors[k]);
        CAPTURE(k, order);
        CHECK(order > 0.9);
    }
}

TEST_CASE("damage: explicit and implicit updates of a uniform field follow the local law and agree as dt -> 0",
          "[mpm][damage]")
{
    // Uniform stretch: the same D̃ at every particle, so Δd = 0 and each
    // update is Euler's (forward, backward) on ηḋ = (1 − d)D̃ − d.
    const QrAnisotropic<2> model = disk_material();
    const std::vector<const ConstitutiveModel<2, 2>*> models{&model};
    PhaseFieldPoint<2> field;
    field.eta = 0.1;
    field.l0 = 0.02;
    field.sigma_crit = critical_stress_from_stretch<2>(model, MaterialPoint<2>{}, field, 0.2);
    const Eigen::Matrix2d F = 1.3 * Eigen::Matrix2d::Identity();
    const double D = driving_force<2>(model, F, MaterialPoint<2>{}, field)->current;
    REQUIRE(D > 0.0);
    const double T = 0.05, exact = local_law(D, field.eta, T);
    double explicit_error = 0.0, implicit_error = 0.0, gap = 0.0;
    for (const int steps : {8, 16, 32, 64}) {
        Particles<2> forward = particle_block(0.01, 0, 6, 4, F, field), backward = forward;
        DamageGrid<2> grid(0.01);
        for (int n = 0; n < steps; ++n) {
            REQUIRE(explicit_damage(forward, models, T / steps, grid).failure.empty());
            const DamageReport report = implicit_damage(backward, models, T / steps, {}, grid, cg_solve(1e-14));
            REQUIRE(report.failure.empty());
            REQUIRE(report.cg_converged);
        }
        double spread = 0.0;
        for (std::size_t p = 0; p < forward.point.size(); ++p) {
            spread = std::max(spread, std::abs(forward.point[p].damage - forward.point[0].damage));
            spread = std::max(spread, std::abs(backward.point[p].damage - backward.point[0].damage));
        }
        CHECK(spread < 1e-12);
        const double e_forward = std::abs(forward.point[0].damage - exact);
        const double e_backward = std::abs(backward.point[0].damage - exact);
        const double e_gap = std::abs(forward.point[0].damage - backward.point[0].damage);
        CAPTURE(steps, e_forward, e_backward, e_gap);
        if (steps > 8) {
            // First order: each halving of Δt halves the errors and the gap.
            CHECK(explicit_error / e_forward == Approx(2.0).margin(0.25));
            CHECK(implicit_error / e_backward == Approx(2.0).margin(0.25));
            CHECK(gap / e_gap == Approx(2.0).margin(0.25));
        }
        explicit_error = e_forward;
        implicit_error = e_backward;
        gap = e_gap;
    }
}

TEST_CASE("damage: never decreases, stays in [0, 1], and a stress below sigma_crit damages nothing", "[mpm][damage]")
{
    const QrAnisotropic<2> model = disk_material();
    const std::vector<const ConstitutiveModel<2, 2>*> models{&model};
    PhaseFieldPoint<2> field;
    field.eta = 0.05;
    field.l0 = 0.02;
    const double p = 0.2;
    field.sigma_crit = critical_stress_from_stretch<2>(model, MaterialPoint<2>{}, field, p);
    for (const DamageTransfer transfer : {DamageTransfer::increment, DamageTransfer::seed}) {
        // Below the threshold: uniform stretch 0.9 p.
        Particles<2> calm = particle_block(0.01, 0, 6, 4, (1.0 + 0.9 * p) * Eigen::Matrix2d::Identity(), field);
        Particles<2> calm_explicit = calm;
        DamageGrid<2> grid(0.01);
        for (int n = 0; n < 20; ++n) {
            implicit_damage(calm, models, 0.01, {DamagePreconditioner::lumped, transfer}, grid, cg_solve(1e-12));
            explicit_damage(calm_explicit, models, 0.01, grid);
        }
        for (std::size_t q = 0; q < calm.point.size(); ++q) {
            CHECK(calm.point[q].damage == 0.0);
            CHECK(calm_explicit.point[q].damage == 0.0);
            CHECK(calm.phase_field[q].history == 0.0);
        }
        // Random stretches, some far past the threshold, and a step back to rest half way.
        std::mt19937 rng(17);
        std::uniform_real_distribution<double> stretch(0.9, 1.0 + 4.0 * p);
        Particles<2> implicit_particles = particle_block(0.01, 0, 8, 6, Eigen::Matrix2d::Identity(), field);
        for (auto& F : implicit_particles.F)
            F = Eigen::Vector2d(stretch(rng), stretch(rng)).asDiagonal();
        Particles<2> explicit_particles = implicit_particles;
        for (int n = 0; n < 30; ++n) {
            if (n == 15)
                for (auto* particles : {&implicit_particles, &explicit_particles})
                    for (auto& F : particles->F)
                        F.setIdentity();
            const Particles<2> before_implicit = implicit_particles, before_explicit = explicit_particles;
            // Δt l₀²/η well inside explicit diffusion's stability bound.
            const DamageReport report =
                implicit_damage(implicit_particles, models, 0.002, {DamagePreconditioner::lumped, transfer}, grid,
                                cg_solve(1e-12));
            REQUIRE(report.cg_converged);
            explicit_damage(explicit_particles, models, 0.002, grid);
            for (std::size_t q = 0; q < implicit_particles.point.size(); ++q) {
                for (const auto& [now, then] : {std::pair{&implicit_particles, &before_implicit},
                                                std::pair{&explicit_particles, &before_explicit}}) {
                    const double d = now->point[q].damage;
                    CHECK(d >= then->point[q].damage);
                    CHECK(d <= 1.0);
                    CHECK(now->phase_field[q].history >= then->phase_field[q].history);
                }
            }
        }
        double damaged = 0.0;
        for (const auto& point : implicit_particles.point)
            damaged = std::max(damaged, point.damage);
        CHECK(damaged > 0.1);
    }
}

TEST_CASE("damage: the two preconditioners solve the same system", "[mpm][damage]")
{
    PhaseFieldPoint<2> field;
    field.l0 = 0.02;
    const Particles<2> particles = particle_block(0.01, 0, 10, 5, Eigen::Matrix2d::Identity(), field);
    DamageGrid<2> grid(0.01);
    damage_to_grid(particles, grid);
    std::vector<double> driving(particles.F.size());
    for (std::size_t q = 0; q < driving.size(); ++q)
        driving[q] = 0.5 + 0.5 * std::sin(static_cast<double>(q));
    const DamageSystem<2> system(particles, driving, 0.5, grid);
    SpdSolveOutcome lumped, full;
    const Eigen::VectorXd a = solve_damage_system(system, grid, {}, DamagePreconditioner::lumped, cg_solve(1e-13), lumped);
    const Eigen::VectorXd b =
        solve_damage_system(system, grid, {}, DamagePreconditioner::full_diagonal, cg_solve(1e-13), full);
    REQUIRE(lumped.converged);
    REQUIRE(full.converged);
    CHECK((a - b).cwiseAbs().maxCoeff() < 1e-10);
    Eigen::VectorXd residual;
    system.multiply(a, residual);
    CHECK((residual - system.rhs()).norm() <= 1e-12 * system.rhs().norm());
}
