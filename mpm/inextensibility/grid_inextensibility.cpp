#include "sinew/mpm/inextensibility/grid_inextensibility.hpp"

#include "sinew/mpm/inextensibility/inextensibility_rows.hpp"

#include <chrono>

namespace sinew {

template <int Dim>
bool any_inextensible(const Particles<Dim>& particles, const InextensibilitySettings& settings)
{
    for (int p = 0; p < particles.size(); ++p)
        if (settings.carries(particles.material[static_cast<std::size_t>(p)]))
            return true;
    return false;
}

template <int Dim>
InextensibilityStepReport project_grid_velocities(const Particles<Dim>& particles, const MpmStepSettings<Dim>& settings,
                                                  const GridInextensibility<Dim>& inextensibility, SparseGrid<Dim>& grid)
{
    const auto start = std::chrono::steady_clock::now();
    InextensibilityStepReport report;
    if (!any_inextensible(particles, inextensibility.settings))
        return report;
    const GridVelocityMap<Dim> map(particles, grid, settings, GridVelocityMap<Dim>::Predictor::grid_velocity);
    const LinearVelocityRows rows =
        inextensibility_rows(particles, map, grid.dx(), inextensibility.settings);
    Eigen::VectorXd y = map.predictor();
    const SchurProjectionReport projection = project_onto_rows(rows, map.variable_masses(), y, inextensibility.solve);
    map.write_velocities(y, grid);
    report.rows = rows.rows();
    report.cg_iterations = projection.solve.iterations;
    report.converged = projection.solve.converged;
    report.violation = projection.violation_after;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

template bool any_inextensible<2>(const Particles<2>&, const InextensibilitySettings&);
template bool any_inextensible<3>(const Particles<3>&, const InextensibilitySettings&);
template InextensibilityStepReport project_grid_velocities<2>(const Particles<2>&, const MpmStepSettings<2>&,
                                                              const GridInextensibility<2>&, SparseGrid<2>&);
template InextensibilityStepReport project_grid_velocities<3>(const Particles<3>&, const MpmStepSettings<3>&,
                                                              const GridInextensibility<3>&, SparseGrid<3>&);

} // namespace sinew
