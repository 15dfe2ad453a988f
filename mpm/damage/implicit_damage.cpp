#include "sinew/mpm/damage/implicit_damage.hpp"

#include "sinew/mpm/damage/particle_driving_forces.hpp"

#include <algorithm>

namespace sinew {
namespace {

/// Σ_i w_ip v_i over particle p's cubic stencil.
template <int Dim>
double interpolate(const Particles<Dim>& particles, const DamageGrid<Dim>& grid, int p, const Eigen::VectorXd& v)
{
    double sum = 0.0;
    for_each_damage_node(particles, grid, p, [&](int slot, double w, const auto&) { sum += w * v[slot]; });
    return sum;
}

/// The particles' d from the solved field: the transfer's value clamped to
/// [d_p, 1], counted in `report`.
template <int Dim>
void damage_to_particles(Particles<Dim>& particles, const DamageGrid<Dim>& grid, const Eigen::VectorXd& before,
                         const Eigen::VectorXd& after, DamageTransfer transfer, DamageReport& report)
{
    const Eigen::VectorXd change = after - before;
    for (int p = 0; p < particles.size(); ++p) {
        double& d = particles.point[static_cast<std::size_t>(p)].damage;
        const double value = transfer == DamageTransfer::seed ? interpolate(particles, grid, p, after)
                                                              : d + interpolate(particles, grid, p, change);
        report.decrease_refused += value < d ? 1 : 0;
        report.capped_at_one += value > 1.0 ? 1 : 0;
        const double next = std::min(1.0, std::max(d, value));
        report.grown += next > d ? 1 : 0;
        d = next;
    }
}

} // namespace

template <int Dim>
Eigen::VectorXd solve_damage_system(const DamageSystem<Dim>& system, const DamageGrid<Dim>& grid,
                                    const std::vector<int>& held, DamagePreconditioner preconditioner,
                                    const SpdSolve& solve, SpdSolveOutcome& outcome)
{
    const int n = system.size();
    Eigen::VectorXd free = Eigen::VectorXd::Zero(n), fixed = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < n; ++i)
        free[i] = grid.weight[static_cast<std::size_t>(i)] > 0.0 ? 1.0 : 0.0;
    for (const int i : held) {
        free[i] = 0.0;
        fixed[i] = 1.0;
    }
    // S on the free slots: x ↦ P S P x with P the free slots' projection.
    const auto multiply = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out) {
        system.multiply(free.cwiseProduct(x), out);
        out = free.cwiseProduct(out);
    };
    Eigen::VectorXd b;
    system.multiply(fixed, b);
    b = free.cwiseProduct(system.rhs() - b);  // c − S d_held on the free slots
    const Eigen::VectorXd& chosen =
        preconditioner == DamagePreconditioner::lumped ? system.lumped_diagonal() : system.full_diagonal();
    const Eigen::VectorXd diagonal = free.cwiseProduct(chosen) + (Eigen::VectorXd::Ones(n) - free);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    outcome = solve(multiply, diagonal, b, x);
    return free.cwiseProduct(x) + fixed;
}

template <int Dim>
DamageReport implicit_damage(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                             double dt, const ImplicitDamageSettings& settings, DamageGrid<Dim>& grid,
                             const SpdSolve& solve)
{
    DamageReport report;
    std::vector<double> driving;
    report.failure = start_damage_update(particles, models, driving, grid);
    if (!report.failure.empty())
        return report;
    const Eigen::VectorXd before = Eigen::Map<const Eigen::VectorXd>(grid.damage.data(), grid.nodes.slots());
    const DamageSystem<Dim> system(particles, driving, dt, grid);
    SpdSolveOutcome outcome;
    const Eigen::VectorXd after = solve_damage_system(system, grid, {}, settings.preconditioner, solve, outcome);
    report.cg_iterations = outcome.iterations;
    report.cg_residual = outcome.relative_residual;
    report.cg_converged = outcome.converged;
    damage_to_particles(particles, grid, before, after, settings.transfer, report);
    grid.damage.assign(after.data(), after.data() + after.size());
    return report;
}

template Eigen::VectorXd solve_damage_system<2>(const DamageSystem<2>&, const DamageGrid<2>&, const std::vector<int>&,
                                                DamagePreconditioner, const SpdSolve&, SpdSolveOutcome&);
template Eigen::VectorXd solve_damage_system<3>(const DamageSystem<3>&, const DamageGrid<3>&, const std::vector<int>&,
                                                DamagePreconditioner, const SpdSolve&, SpdSolveOutcome&);
template DamageReport implicit_damage<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&, double,
                                         const ImplicitDamageSettings&, DamageGrid<2>&, const SpdSolve&);
template DamageReport implicit_damage<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&, double,
                                         const ImplicitDamageSettings&, DamageGrid<3>&, const SpdSolve&);

} // namespace sinew
