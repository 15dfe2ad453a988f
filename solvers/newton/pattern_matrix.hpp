#pragma once
#include "sinew/problems/nlp.hpp"
#include "sinew/solvers/linear/linear_solver.hpp"

#include <vector>

namespace sinew {

/// A compressed sparse matrix with the structure of an Nlp's Hessian pattern,
/// built once; refilled from the pattern-ordered values without allocating.
/// Repeated (row, col) entries of the pattern are summed into one nonzero.
class PatternMatrix {
public:
    PatternMatrix(const SparsityPattern& pattern, int size);

    /// A's values from values in pattern order (lower triangle, as Nlp gives).
    void fill(const Eigen::VectorXd& pattern_values);
    /// A += shift·I (the diagonal is always in the structure).
    void shift_diagonal(double shift);
    /// Rows and columns i with fixed[i] != 0 become those of the identity
    /// (a variable held at an active bound gets a zero step).
    void fix_variables(const std::vector<char>& fixed);

    const SparseMatrix& matrix() const { return matrix_; }

private:
    SparseMatrix matrix_;
    std::vector<int> value_index_;     ///< nonzero of A for each pattern entry
    std::vector<int> diagonal_index_;  ///< nonzero of A for each (i, i)
};

} // namespace sinew
