#include "sinew/mpm/step_settings.hpp"

namespace sinew {

template <int Dim>
std::vector<NodeContact<Dim>> node_contacts(const MpmStepSettings<Dim>& settings, const Eigen::Matrix<double, Dim, 1>& x,
                                            double dx)
{
    std::vector<NodeContact<Dim>> contacts;
    if (settings.walls)
        add_wall_contacts(*settings.walls, x, dx, contacts);
    add_collider_contacts(settings.colliders, x, dx, contacts);
    return contacts;
}

template <int Dim>
void apply_grid_conditions(const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid)
{
    if (settings.walls || !settings.colliders.empty())
        apply_node_contacts(grid, [&](const Eigen::Matrix<double, Dim, 1>& x) { return node_contacts(settings, x, grid.dx()); });
}

template <int Dim>
void advect_particles(const MpmStepSettings<Dim>& settings, const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout,
                      Particles<Dim>& particles)
{
    grid_to_particles_advected(grid, layout, settings.transfer, settings.time_step, particles);
}

template <int Dim>
void finish_step(const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout,
                 Particles<Dim>& particles)
{
    apply_grid_conditions(settings, grid);
    advect_particles(settings, grid, layout, particles);
}

template std::vector<NodeContact<2>> node_contacts<2>(const MpmStepSettings<2>&, const Eigen::Vector2d&, double);
template std::vector<NodeContact<3>> node_contacts<3>(const MpmStepSettings<3>&, const Eigen::Vector3d&, double);
template void apply_grid_conditions<2>(const MpmStepSettings<2>&, SparseGrid<2>&);
template void apply_grid_conditions<3>(const MpmStepSettings<3>&, SparseGrid<3>&);
template void advect_particles<2>(const MpmStepSettings<2>&, const SparseGrid<2>&, const ParticleBuckets<2>&, Particles<2>&);
template void advect_particles<3>(const MpmStepSettings<3>&, const SparseGrid<3>&, const ParticleBuckets<3>&, Particles<3>&);
template void finish_step<2>(const MpmStepSettings<2>&, SparseGrid<2>&, const ParticleBuckets<2>&, Particles<2>&);
template void finish_step<3>(const MpmStepSettings<3>&, SparseGrid<3>&, const ParticleBuckets<3>&, Particles<3>&);

} // namespace sinew
