#include "sinew/mpm/grid_walls.hpp"

#include "sinew/core/input_error.hpp"


namespace sinew {

WallCondition wall_condition(const std::string& name)
{
    if (name == "sticky")
        return WallCondition::sticky;
    if (name == "slip")
        return WallCondition::slip;
    if (name == "separate")
        return WallCondition::separate;
    throw InputError("wall condition '" + name + "' is unknown; it must be one of: sticky, slip, separate");
}

template <int Dim>
GridWalls<Dim> GridWalls<Dim>::box(const Eigen::Matrix<double, Dim, 1>& lower,
                                   const Eigen::Matrix<double, Dim, 1>& upper, WallCondition condition)
{
    GridWalls walls;
    walls.lower = lower;
    walls.upper = upper;
    for (auto& faces : walls.condition)
        faces = {condition, condition};
    return walls;
}

namespace {

/// v after a wall of outward normal ±e_axis (sign = −1 lower face, +1 upper).
template <int Dim>
void apply_face(WallCondition condition, int axis, double sign, Eigen::Matrix<double, Dim, 1>& v)
{
    const double outward = sign * v[axis];  // v·n, n the wall's outward normal
    switch (condition) {
    case WallCondition::sticky: v.setZero(); break;
    case WallCondition::slip: v[axis] = 0.0; break;
    case WallCondition::separate:
        if (outward > 0.0)
            v[axis] = 0.0;
        break;
    }
}

} // namespace

template <int Dim>
void apply_walls(const GridWalls<Dim>& walls, SparseGrid<Dim>& grid)
{
    const double band = walls.thickness * grid.dx();
    for (int slot = 0; slot < grid.slots(); ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        if (!(grid.mass[s] > 0.0))
            continue;
        const auto x = grid.position(slot);
        for (int a = 0; a < Dim; ++a) {
            if (x[a] < walls.lower[a] + band)
                apply_face<Dim>(walls.condition[static_cast<std::size_t>(a)][0], a, -1.0, grid.velocity[s]);
            if (x[a] > walls.upper[a] - band)
                apply_face<Dim>(walls.condition[static_cast<std::size_t>(a)][1], a, 1.0, grid.velocity[s]);
        }
    }
}

template struct GridWalls<2>;
template struct GridWalls<3>;
template void apply_walls<2>(const GridWalls<2>&, SparseGrid<2>&);
template void apply_walls<3>(const GridWalls<3>&, SparseGrid<3>&);

} // namespace sinew
