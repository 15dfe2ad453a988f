#pragma once
#include "sinew/mpm/sparse_grid.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace sinew {

/// The part of the grid the particles reach, for output: the nodes with
/// mass (by slot, so one input gives one order) and the cells all of whose
/// 2^d corners have mass, each by its corners' indices into `slots` in
/// VTK's order (corner c at the cell's lower node plus e_a for every bit a
/// of c; write_cell_vtu).
template <int Dim>
struct ActiveGrid {
    std::vector<int> slots;                          ///< the nodes with mass
    std::vector<std::array<int, (1 << Dim)>> cells;  ///< corners, as indices into slots
    Eigen::MatrixXd positions;                       ///< Dim × slots.size(), x_i = i dx
};

template <int Dim>
ActiveGrid<Dim> active_grid(const SparseGrid<Dim>& grid);

} // namespace sinew
