#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"

#include <string>

namespace sinew {

/// Which entries of a matrix a solver reads.
enum class EntriesRead {
    all,             ///< general solvers (LU)
    lower_triangle,  ///< symmetric solvers: entries above the diagonal are ignored
};

/// Why A cannot be factorized ("matrix is 4x5, not square", "entry (3, 7) is
/// not finite"), or an empty string when it can be tried. Only the entries the
/// solver reads are checked: a NaN above the diagonal does not matter to a
/// symmetric solver.
std::string describe_unusable_matrix(const SparseMatrix& A, EntriesRead read);

/// Why solve(b) cannot be tried: no successful factorization, or b's size
/// differs from the factorized matrix's `rows`; an empty string when it can.
std::string describe_unusable_solve(bool factorized, Eigen::Index rhs_size, Eigen::Index rows);

/// A itself when it is compressed; otherwise a compressed copy put in `storage`.
/// Solvers read the raw column-pointer / row-index / value arrays, which are
/// only contiguous in compressed form.
const SparseMatrix& compressed(const SparseMatrix& A, SparseMatrix& storage);

} // namespace sinew
