#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"

#include <vector>

namespace sinew {

/// The full compressed-row (CSR) form of a symmetric matrix given by its
/// lower triangle, as a solver that stores both triangles wants it (PETSc's
/// AIJ), with the map from each lower-triangle entry to its one or two
/// places. Built once per sparsity pattern; fill() then writes a matrix of
/// that pattern's values in one pass, without searching or sorting.
class SymmetricCsr {
public:
    /// The structure of the full matrix whose lower triangle has the pattern
    /// of the compressed matrix `lower` (entries above the diagonal ignored).
    explicit SymmetricCsr(const SparseMatrix& lower);

    /// Row r's entries are at [row_starts()[r], row_starts()[r + 1]), their
    /// columns ascending in columns().
    const std::vector<int>& row_starts() const { return row_starts_; }
    const std::vector<int>& columns() const { return columns_; }
    int rows() const { return static_cast<int>(row_starts_.size()) - 1; }
    int nonzeros() const { return static_cast<int>(columns_.size()); }

    /// values[p] = the full matrix's entry at CSR position p, for `lower`
    /// with the pattern this was built from; `values` holds nonzeros().
    void fill(const SparseMatrix& lower, double* values) const;

private:
    std::vector<int> row_starts_;
    std::vector<int> columns_;
    /// Entry k of `lower` (in its storage order), at row i and column j,
    /// goes to below_[k] (row i, column j) when i ≥ j, and also to
    /// above_[k] (row j, column i) when i > j. Both are −1 for an entry above
    /// the diagonal (not read); above_[k] is −1 on the diagonal.
    std::vector<int> below_;
    std::vector<int> above_;
};

} // namespace sinew
