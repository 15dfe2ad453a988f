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
void finish_step(const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid, Particles<Dim>& particles)
{
    using Matrix = typename Particles<Dim>::Matrix;
    for (int slot = 0; slot < grid.slots(); ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        if (grid.mass[s] > 0.0)
            grid.velocity[s] = conditioned_velocity(node_contacts(settings, grid.position(slot), grid.dx()), grid.velocity[s]);
    }
    grid_to_particles(grid, settings.transfer, particles);
    const double h = settings.time_step;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        particles.x[i] += h * particles.v[i];
        particles.F[i] = (Matrix::Identity() + h * particles.C[i]) * particles.F[i];  // Fⁿ⁺¹ = (I + Δt ∇v) Fⁿ
    }
}

template std::vector<NodeContact<2>> node_contacts<2>(const MpmStepSettings<2>&, const Eigen::Vector2d&, double);
template std::vector<NodeContact<3>> node_contacts<3>(const MpmStepSettings<3>&, const Eigen::Vector3d&, double);
template void finish_step<2>(const MpmStepSettings<2>&, SparseGrid<2>&, Particles<2>&);
template void finish_step<3>(const MpmStepSettings<3>&, SparseGrid<3>&, Particles<3>&);

} // namespace sinew
