#include "sinew/mpm/implicit_step.hpp"

#include "sinew/mpm/grid_velocity_nlp.hpp"
#include "sinew/mpm/inextensibility/inextensibility_rows.hpp"

#include <chrono>
#include <cmath>
#include <utility>

namespace sinew {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

template <int Dim>
ImplicitStepReport implicit_step(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                 const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid,
                                 const GridVelocitySolve& solve, const GridInextensibility<Dim>* inextensibility)
{
    ImplicitStepReport report;
    const ParticleBuckets<Dim> layout = particles_to_grid(particles, settings.transfer, grid);
    GridVelocityMap<Dim> map(particles, grid, settings, GridVelocityMap<Dim>::Predictor::momentum_and_gravity);
    auto start = std::chrono::steady_clock::now();
    LinearVelocityRows rows;
    const bool constrained = inextensibility && any_inextensible(particles, inextensibility->settings);
    if (constrained)
        rows = inextensibility_rows(particles, map, grid.dx(), inextensibility->settings);
    const bool in_solve = constrained && inextensibility->settings.method == InextensibilityMethod::nlp;
    if (in_solve)
        rows = independent_rows(rows);  // Newton's KKT systems need a Jacobian of full row rank
    report.inextensibility.rows = rows.rows();
    report.inextensibility.seconds = seconds_since(start);
    GridVelocityNlp<Dim> nlp(particles, models, std::move(map), layout, settings.time_step,
                             in_solve ? rows : LinearVelocityRows{});
    report.unknowns = nlp.num_variables();
    Eigen::VectorXd v = nlp.starting_point();
    if (!std::isfinite(nlp.objective(v))) {
        report.failure = "the elastic energy of the particles is not finite at the implicit step's starting velocities";
        return report;
    }
    report.converged = nlp.num_variables() == 0 || solve(nlp, v);  // every node held: nothing to solve
    if (constrained && !in_solve) {
        start = std::chrono::steady_clock::now();
        const SchurProjectionReport projection =
            project_onto_rows(rows, nlp.map().variable_masses(), v, inextensibility->solve);
        report.inextensibility.cg_iterations = projection.solve.iterations;
        report.inextensibility.converged = projection.solve.converged;
        report.inextensibility.seconds += seconds_since(start);
    }
    report.inextensibility.violation = rows.violation(v);
    nlp.map().write_velocities(v, grid);
    finish_step(settings, grid, layout, particles);
    return report;
}

template ImplicitStepReport implicit_step<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&,
                                             const MpmStepSettings<2>&, SparseGrid<2>&, const GridVelocitySolve&,
                                             const GridInextensibility<2>*);
template ImplicitStepReport implicit_step<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&,
                                             const MpmStepSettings<3>&, SparseGrid<3>&, const GridVelocitySolve&,
                                             const GridInextensibility<3>*);

} // namespace sinew
