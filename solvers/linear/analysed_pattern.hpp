#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"

#include <vector>

namespace sinew {

/// The sparsity pattern of the matrix a solver last analysed symbolically.
/// A new matrix needs a new symbolic analysis unless its pattern is exactly
/// this one: same dimensions, same column pointers, same row indices. Values
/// are not compared. Only compressed matrices are compared or remembered
/// (see compressed() in matrix_input.hpp).
class AnalysedPattern {
public:
    /// True when the compressed matrix A has exactly the remembered pattern.
    bool matches(const SparseMatrix& A) const;
    /// Remembers the pattern of the compressed matrix A.
    void remember(const SparseMatrix& A);
    /// Forgets the pattern, so that the next matrix is analysed whatever it is.
    void forget();

private:
    bool known_ = false;
    Eigen::Index rows_ = 0;
    std::vector<int> column_starts_;
    std::vector<int> row_indices_;
};

} // namespace sinew
