#include "sinew/mpm/grid_walls.hpp"

namespace sinew {

template <int Dim>
GridWalls<Dim> GridWalls<Dim>::box(const Eigen::Matrix<double, Dim, 1>& lower,
                                   const Eigen::Matrix<double, Dim, 1>& upper, GridCondition condition)
{
    GridWalls walls;
    walls.lower = lower;
    walls.upper = upper;
    for (auto& faces : walls.condition)
        faces = {condition, condition};
    return walls;
}

template <int Dim>
void add_wall_contacts(const GridWalls<Dim>& walls, const Eigen::Matrix<double, Dim, 1>& x, double dx,
                       std::vector<NodeContact<Dim>>& contacts)
{
    using Vector = Eigen::Matrix<double, Dim, 1>;
    const double band = walls.thickness * dx;
    for (int a = 0; a < Dim; ++a) {
        const Vector into_domain = Vector::Unit(a);  // the lower face's normal; the upper face's is −e_a
        const auto& faces = walls.condition[static_cast<std::size_t>(a)];
        if (x[a] < walls.lower[a] + band)
            contacts.push_back({faces[0], Vector::Zero(), into_domain});
        if (x[a] > walls.upper[a] - band)
            contacts.push_back({faces[1], Vector::Zero(), -into_domain});
    }
}

template <int Dim>
void apply_walls(const GridWalls<Dim>& walls, SparseGrid<Dim>& grid)
{
    apply_node_contacts(grid, [&](const Eigen::Matrix<double, Dim, 1>& x) {
        std::vector<NodeContact<Dim>> contacts;
        add_wall_contacts(walls, x, grid.dx(), contacts);
        return contacts;
    });
}

template struct GridWalls<2>;
template struct GridWalls<3>;
template void add_wall_contacts<2>(const GridWalls<2>&, const Eigen::Vector2d&, double, std::vector<NodeContact<2>>&);
template void add_wall_contacts<3>(const GridWalls<3>&, const Eigen::Vector3d&, double, std::vector<NodeContact<3>>&);
template void apply_walls<2>(const GridWalls<2>&, SparseGrid<2>&);
template void apply_walls<3>(const GridWalls<3>&, SparseGrid<3>&);

} // namespace sinew
