#include "sinew/mpm/grid_colliders.hpp"

namespace sinew {

template <int Dim>
void apply_colliders(const std::vector<GridCollider<Dim>>& colliders, SparseGrid<Dim>& grid)
{
    using Vector = Eigen::Matrix<double, Dim, 1>;
    for (const GridCollider<Dim>& collider : colliders)
        for (int slot = 0; slot < grid.slots(); ++slot) {
            const auto s = static_cast<std::size_t>(slot);
            if (!(grid.mass[s] > 0.0))
                continue;
            Eigen::Vector3d x = Eigen::Vector3d::Zero();  // a 2D node as (x, y, 0)
            x.head<Dim>() = grid.position(slot);
            const BodyDistance d = collider.body->distance(x);
            if (!(d.distance < collider.thickness * grid.dx()))
                continue;
            const Vector n = d.gradient.head<Dim>();
            grid.velocity[s] = n.squaredNorm() > 0.0
                                   ? conditioned_velocity<Dim>(collider.condition, grid.velocity[s], collider.velocity, n)
                                   : collider.velocity;
        }
}

template void apply_colliders<2>(const std::vector<GridCollider<2>>&, SparseGrid<2>&);
template void apply_colliders<3>(const std::vector<GridCollider<3>>&, SparseGrid<3>&);

} // namespace sinew
