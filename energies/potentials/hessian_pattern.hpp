#pragma once
#include "sinew/energies/potentials/potential.hpp"

#include <Eigen/Core>

#include <vector>

namespace sinew {

/// The lower triangle of a Hessian over node-major coordinates
/// (row = node·dimension + component), built once from the stencils of the
/// potentials it serves: the dense dimension × dimension block of every pair
/// of nodes that share a stencil, and the diagonal block of every node (so
/// that a solver can always shift the diagonal).
///
/// Entries are in compressed-column order (by column, then row) and unique.
/// A node's block column is laid out as: its own diagonal block, then one
/// full block per coupled node of larger index, in increasing node order.
class HessianPattern {
public:
    /// Throws InputError for a stencil node out of [0, num_nodes) or a stencil
    /// that lists a node twice (a degenerate element).
    HessianPattern(int dimension, int num_nodes, const std::vector<const Stencils*>& stencil_sets);

    int dimension() const { return dimension_; }
    int num_nodes() const { return num_nodes_; }
    int num_coordinates() const { return dimension_ * num_nodes_; }
    int nonzeros() const { return static_cast<int>(rows_.size()); }

    /// Row and column of every nonzero (row ≥ col), in the pattern's order.
    const std::vector<int>& rows() const { return rows_; }
    const std::vector<int>& cols() const { return cols_; }

    /// Index of nonzero (row, col), row ≥ col; −1 when the pattern lacks it.
    int find(int row, int col) const;

    /// The slot table of `stencils` (see StencilSlots): every stencil must be
    /// covered by the pattern, as those it was built from are.
    StencilSlots slots(const Stencils& stencils) const;

private:
    /// Index of the entry (node_i·d + n, node_j·d + m) for node_i ≥ node_j.
    int block_entry(int node_i, int node_j, int n, int m) const;

    int dimension_;
    int num_nodes_;
    /// Coupled nodes of larger index per node, CSR (sorted within a node).
    std::vector<int> neighbor_starts_;
    std::vector<int> neighbors_;
    /// First nonzero of each coordinate column, and one past the last.
    std::vector<int> column_starts_;
    std::vector<int> rows_;
    std::vector<int> cols_;
};

/// values[slots[k]] += H(p, q) for the lower-triangle entries of the local
/// Hessian H in StencilSlots order; `slots` points at one stencil's column.
template <typename LocalHessian>
inline void add_lower_triangle(const LocalHessian& H, const int* slots, double* values)
{
    int k = 0;
    for (int q = 0; q < H.cols(); ++q)
        for (int p = q; p < H.rows(); ++p)
            values[slots[k++]] += H(p, q);
}

} // namespace sinew
