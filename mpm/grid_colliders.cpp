#include "sinew/mpm/grid_colliders.hpp"

namespace sinew {

template <int Dim>
void add_collider_contacts(const std::vector<GridCollider<Dim>>& colliders, const Eigen::Matrix<double, Dim, 1>& x,
                           double dx, std::vector<NodeContact<Dim>>& contacts)
{
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  // a 2D node as (x, y, 0)
    point.head<Dim>() = x;
    for (const GridCollider<Dim>& collider : colliders) {
        const BodyDistance d = collider.body->distance(point);
        if (d.distance < collider.thickness * dx)
            contacts.push_back({collider.condition, collider.velocity_at(x), d.gradient.head<Dim>()});
    }
}

template <int Dim>
void apply_colliders(const std::vector<GridCollider<Dim>>& colliders, SparseGrid<Dim>& grid)
{
    apply_node_contacts(grid, [&](const Eigen::Matrix<double, Dim, 1>& x) {
        std::vector<NodeContact<Dim>> contacts;
        add_collider_contacts(colliders, x, grid.dx(), contacts);
        return contacts;
    });
}

template void add_collider_contacts<2>(const std::vector<GridCollider<2>>&, const Eigen::Vector2d&, double,
                                       std::vector<NodeContact<2>>&);
template void add_collider_contacts<3>(const std::vector<GridCollider<3>>&, const Eigen::Vector3d&, double,
                                       std::vector<NodeContact<3>>&);
template void apply_colliders<2>(const std::vector<GridCollider<2>>&, SparseGrid<2>&);
template void apply_colliders<3>(const std::vector<GridCollider<3>>&, SparseGrid<3>&);

} // namespace sinew
