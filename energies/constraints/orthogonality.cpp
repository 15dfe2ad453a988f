#include "sinew/energies/constraints/orthogonality.hpp"

#include "sinew/core/input_error.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

/// The pairs i ≤ j of the constraints, in order.
constexpr int kPairs[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};

} // namespace

Orthogonality::Orthogonality(std::string name, int offset) : name_(std::move(name)), offset_(offset)
{
    if (offset < 0)
        throw InputError("orthogonality constraint '" + name_ + "': offset " + std::to_string(offset) + " is negative");
    // Jacobian: row p = (i, j), the entries M_ki and M_kj for each k (once when i = j).
    for (int p = 0; p < 6; ++p) {
        const int i = kPairs[p][0], j = kPairs[p][1];
        for (int k = 0; k < 3; ++k) {
            jacobian_pattern_.add(p, entry(k, i));
            if (j != i)
                jacobian_pattern_.add(p, entry(k, j));
        }
    }
    // Hessian (lower triangle): for i = j the diagonal (M_ki, M_ki); for i < j
    // the diagonals of M_ki and M_kj (used by the projection) and (M_kj, M_ki).
    for (int p = 0; p < 6; ++p) {
        const int i = kPairs[p][0], j = kPairs[p][1];
        for (int k = 0; k < 3; ++k) {
            hessian_pattern_.add(entry(k, i), entry(k, i));
            if (j != i) {
                hessian_pattern_.add(entry(k, j), entry(k, j));
                hessian_pattern_.add(entry(k, j), entry(k, i));  // entry(k, j) > entry(k, i) as j > i
            }
        }
    }
}

void Orthogonality::values(ConstVectorRef x, VectorRef c)
{
    for (int p = 0; p < 6; ++p) {
        const int i = kPairs[p][0], j = kPairs[p][1];
        double sum = 0.0;
        for (int k = 0; k < 3; ++k)
            sum += x[entry(k, i)] * x[entry(k, j)];
        c[p] = sum - (i == j ? 1.0 : 0.0);  // c_ij = (MᵀM)_ij − δ_ij
    }
}

void Orthogonality::jacobian_values(ConstVectorRef x, VectorRef values)
{
    int q = 0;
    for (int p = 0; p < 6; ++p) {
        const int i = kPairs[p][0], j = kPairs[p][1];
        for (int k = 0; k < 3; ++k) {
            if (j == i) {
                values[q++] = 2.0 * x[entry(k, i)];  // ∂c_ii/∂M_ki = 2M_ki
            } else {
                values[q++] = x[entry(k, j)];  // ∂c_ij/∂M_ki = M_kj
                values[q++] = x[entry(k, i)];  // ∂c_ij/∂M_kj = M_ki
            }
        }
    }
}

void Orthogonality::hessian_values(ConstVectorRef, ConstVectorRef lambda, Projection projection, VectorRef values)
{
    const bool clamp = projection == Projection::clamp;
    int q = 0;
    for (int p = 0; p < 6; ++p) {
        const int i = kPairs[p][0], j = kPairs[p][1];
        const double l = lambda[p];
        for (int k = 0; k < 3; ++k) {
            if (j == i) {
                values[q++] = clamp ? std::max(2.0 * l, 0.0) : 2.0 * l;  // λ ∂²c_ii/∂M_ki²
            } else {
                // λ[0 1; 1 0] on (M_ki, M_kj); projected: (|λ|/2)[1 s; s 1].
                const double diagonal = clamp ? 0.5 * std::abs(l) : 0.0;
                values[q++] = diagonal;
                values[q++] = diagonal;
                values[q++] = clamp ? 0.5 * l : l;
            }
        }
    }
}

double Orthogonality::violation(ConstVectorRef x) const
{
    Eigen::Matrix3d M;
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i)
            M(k, i) = x[entry(k, i)];
    return (M.transpose() * M - Eigen::Matrix3d::Identity()).norm();
}

} // namespace sinew
