#include "sinew/solvers/linear/matrix_input.hpp"

#include <cmath>

namespace sinew {

std::string describe_unusable_matrix(const SparseMatrix& A, EntriesRead read)
{
    if (A.rows() != A.cols())
        return "matrix is " + std::to_string(A.rows()) + "x" + std::to_string(A.cols()) + ", not square";
    for (Eigen::Index j = 0; j < A.outerSize(); ++j)
        for (SparseMatrix::InnerIterator entry(A, j); entry; ++entry)
            if ((read == EntriesRead::all || entry.row() >= entry.col()) && !std::isfinite(entry.value()))
                return "matrix entry (" + std::to_string(entry.row()) + ", " + std::to_string(entry.col()) +
                       ") is not finite";
    return {};
}

std::string describe_unusable_solve(bool factorized, Eigen::Index rhs_size, Eigen::Index rows)
{
    if (!factorized)
        return "solve called without a successful factorization";
    if (rhs_size != rows)
        return "right-hand side has size " + std::to_string(rhs_size) + ", matrix has " + std::to_string(rows) +
               " rows";
    return "";
}

const SparseMatrix& compressed(const SparseMatrix& A, SparseMatrix& storage)
{
    if (A.isCompressed())
        return A;
    storage = A;
    storage.makeCompressed();
    return storage;
}

} // namespace sinew
