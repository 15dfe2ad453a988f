#pragma once
#include "sinew/mpm/grid_condition.hpp"
#include "sinew/mpm/sparse_grid.hpp"

#include <array>
#include <vector>

namespace sinew {

/// The axis-aligned walls of the domain [lower, upper] (MPM's usual grid
/// boundary, as ziran2020 and mpm88 apply it): a node within `thickness`
/// cells of a face, or beyond it, gets that face's condition (a wall at
/// rest, its normal into the domain) after the grid update, so that no
/// particle's velocity carries it through the wall.
/// Nodes near two faces get both.
template <int Dim>
struct GridWalls {
    Eigen::Matrix<double, Dim, 1> lower = Eigen::Matrix<double, Dim, 1>::Zero();
    Eigen::Matrix<double, Dim, 1> upper = Eigen::Matrix<double, Dim, 1>::Ones();
    /// The condition of the lower and upper face of each axis.
    std::array<std::array<GridCondition, 2>, Dim> condition{};
    double thickness = 2.0;  ///< in cells of dx

    /// Every face with the same condition.
    static GridWalls box(const Eigen::Matrix<double, Dim, 1>& lower, const Eigen::Matrix<double, Dim, 1>& upper,
                         GridCondition condition);
};

/// Appends the walls holding the node at x (grid spacing dx) to `contacts`,
/// lower face before upper, axis by axis.
template <int Dim>
void add_wall_contacts(const GridWalls<Dim>& walls, const Eigen::Matrix<double, Dim, 1>& x, double dx,
                       std::vector<NodeContact<Dim>>& contacts);

/// Applies the walls to the velocity of every node with mass.
template <int Dim>
void apply_walls(const GridWalls<Dim>& walls, SparseGrid<Dim>& grid);

} // namespace sinew
