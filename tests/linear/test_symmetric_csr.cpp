#include "sinew/solvers/linear/symmetric_csr.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace {

using sinew::SparseMatrix;
using sinew::SymmetricCsr;

/// The dense matrix SymmetricCsr's structure and fill() describe.
Eigen::MatrixXd dense_from(const SymmetricCsr& csr, const std::vector<double>& values)
{
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(csr.rows(), csr.rows());
    for (int r = 0; r < csr.rows(); ++r)
        for (int p = csr.row_starts()[r]; p < csr.row_starts()[r + 1]; ++p)
            dense(r, csr.columns()[p]) = values[p];
    return dense;
}

/// Columns strictly ascending within every row: CSR as PETSc wants it.
bool rows_sorted(const SymmetricCsr& csr)
{
    for (int r = 0; r < csr.rows(); ++r)
        for (int p = csr.row_starts()[r] + 1; p < csr.row_starts()[r + 1]; ++p)
            if (csr.columns()[p - 1] >= csr.columns()[p])
                return false;
    return true;
}

/// A random n×n sparse matrix with entries anywhere (those above the diagonal
/// must be ignored), some rows left empty.
SparseMatrix random_matrix(int n, std::mt19937& rng)
{
    std::uniform_int_distribution<int> index(0, n - 1);
    std::uniform_real_distribution<double> value(-2.0, 2.0);
    std::vector<Eigen::Triplet<double>> entries;
    for (int e = 0; e < 4 * n; ++e)
        entries.emplace_back(index(rng), index(rng), value(rng));
    for (int i = 0; i < n; i += 3)
        entries.emplace_back(i, i, value(rng));
    SparseMatrix A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    A.makeCompressed();
    return A;
}

} // namespace

TEST_CASE("SymmetricCsr gives the full symmetric matrix of a lower triangle in sorted CSR")
{
    std::mt19937 rng(20261204);
    for (int n : {1, 2, 7, 40, 300}) {
        const SparseMatrix A = random_matrix(n, rng);
        const SymmetricCsr csr(A);
        std::vector<double> values(static_cast<size_t>(csr.nonzeros()), std::nan(""));
        csr.fill(A, values.data());
        const Eigen::MatrixXd lower = Eigen::MatrixXd(A).triangularView<Eigen::Lower>();
        const Eigen::MatrixXd expected = Eigen::MatrixXd(lower.selfadjointView<Eigen::Lower>());
        CAPTURE(n);
        CHECK(rows_sorted(csr));
        CHECK(dense_from(csr, values) == expected);
        // every stored entry written: the structure holds exactly the lower
        // triangle's entries and their mirror images
        const long off_diagonal = SparseMatrix(A.triangularView<Eigen::StrictlyLower>()).nonZeros();
        const long diagonal = SparseMatrix(A.triangularView<Eigen::Lower>()).nonZeros() - off_diagonal;
        CHECK(csr.nonzeros() == diagonal + 2 * off_diagonal);
        for (double v : values)
            CHECK(std::isfinite(v));
    }
}

TEST_CASE("SymmetricCsr sorts the rows of a matrix whose row indices are not ascending")
{
    // column 0 holds rows 3, 0, 2 (in that order), column 1 rows 3, 1
    const std::vector<int> column_starts = {0, 3, 5, 6, 7};
    const std::vector<int> row_indices = {3, 0, 2, 3, 1, 2, 3};
    const std::vector<double> values = {4.0, 1.0, 3.0, 6.0, 5.0, 7.0, 8.0};
    const SparseMatrix A = Eigen::Map<const SparseMatrix>(4, 4, 7, column_starts.data(), row_indices.data(),
                                                          values.data());
    REQUIRE(A.innerIndexPtr()[0] == 3);  // the copy kept the order
    const SymmetricCsr csr(A);
    std::vector<double> full(static_cast<size_t>(csr.nonzeros()));
    csr.fill(A, full.data());
    Eigen::MatrixXd expected(4, 4);
    expected << 1, 0, 3, 4,  //
        0, 5, 0, 6,          //
        3, 0, 7, 0,          //
        4, 6, 0, 8;
    CHECK(rows_sorted(csr));
    CHECK(dense_from(csr, full) == expected);
}
