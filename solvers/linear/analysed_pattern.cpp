#include "sinew/solvers/linear/analysed_pattern.hpp"

#include <algorithm>

namespace sinew {

bool AnalysedPattern::matches(const SparseMatrix& A) const
{
    if (!known_ || A.rows() != rows_ || A.cols() + 1 != static_cast<Eigen::Index>(column_starts_.size()) ||
        A.nonZeros() != static_cast<Eigen::Index>(row_indices_.size()))
        return false;
    return std::equal(column_starts_.begin(), column_starts_.end(), A.outerIndexPtr()) &&
           std::equal(row_indices_.begin(), row_indices_.end(), A.innerIndexPtr());
}

void AnalysedPattern::remember(const SparseMatrix& A)
{
    known_ = true;
    rows_ = A.rows();
    column_starts_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1);
    row_indices_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
}

void AnalysedPattern::forget()
{
    known_ = false;
    column_starts_.clear();
    row_indices_.clear();
}

} // namespace sinew
