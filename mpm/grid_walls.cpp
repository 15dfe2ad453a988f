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
void apply_walls(const GridWalls<Dim>& walls, SparseGrid<Dim>& grid)
{
    using Vector = Eigen::Matrix<double, Dim, 1>;
    const double band = walls.thickness * grid.dx();
    for (int slot = 0; slot < grid.slots(); ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        if (!(grid.mass[s] > 0.0))
            continue;
        const auto x = grid.position(slot);
        const Vector at_rest = Vector::Zero();
        for (int a = 0; a < Dim; ++a) {
            const Vector into_domain = Vector::Unit(a);  // the lower face's normal; the upper face's is −e_a
            const auto& faces = walls.condition[static_cast<std::size_t>(a)];
            if (x[a] < walls.lower[a] + band)
                grid.velocity[s] = conditioned_velocity<Dim>(faces[0], grid.velocity[s], at_rest, into_domain);
            if (x[a] > walls.upper[a] - band)
                grid.velocity[s] = conditioned_velocity<Dim>(faces[1], grid.velocity[s], at_rest, -into_domain);
        }
    }
}

template struct GridWalls<2>;
template struct GridWalls<3>;
template void apply_walls<2>(const GridWalls<2>&, SparseGrid<2>&);
template void apply_walls<3>(const GridWalls<3>&, SparseGrid<3>&);

} // namespace sinew
