#include "sinew/mpm/implicit_step.hpp"

#include "sinew/mpm/grid_velocity_nlp.hpp"

#include <cmath>

namespace sinew {

template <int Dim>
ImplicitStepReport implicit_step(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                 const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid,
                                 const GridVelocitySolve& solve)
{
    ImplicitStepReport report;
    const ParticleBuckets<Dim> layout = particles_to_grid(particles, settings.transfer, grid);
    GridVelocityNlp<Dim> nlp(particles, models, grid, layout, settings);
    report.unknowns = nlp.num_variables();
    Eigen::VectorXd v = nlp.starting_point();
    if (!std::isfinite(nlp.objective(v))) {
        report.failure = "the elastic energy of the particles is not finite at the implicit step's starting velocities";
        return report;
    }
    report.converged = nlp.num_variables() == 0 || solve(nlp, v);  // every node held: nothing to solve
    for (int k = 0; k < nlp.nodes(); ++k)
        grid.velocity[static_cast<std::size_t>(nlp.slot(k))] = nlp.velocity(k, v);
    finish_step(settings, grid, layout, particles);
    return report;
}

template ImplicitStepReport implicit_step<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&,
                                             const MpmStepSettings<2>&, SparseGrid<2>&, const GridVelocitySolve&);
template ImplicitStepReport implicit_step<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&,
                                             const MpmStepSettings<3>&, SparseGrid<3>&, const GridVelocitySolve&);

} // namespace sinew
