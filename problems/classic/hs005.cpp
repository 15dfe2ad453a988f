#include "sinew/problems/classic/hs005.hpp"

#include <cmath>

namespace sinew {

Hs005::Hs005()
{
    hessian_pattern_.add(0, 0);
    hessian_pattern_.add(1, 0);
    hessian_pattern_.add(1, 1);
}

void Hs005::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower << -1.5, -3.0;
    upper << 4.0, 3.0;
}

Nlp::Vector Hs005::starting_point() const
{
    return Vector::Zero(2);
}

double Hs005::objective(ConstVectorRef x)
{
    const double d = x[0] - x[1];
    return std::sin(x[0] + x[1]) + d * d - 1.5 * x[0] + 2.5 * x[1] + 1.0;
}

void Hs005::gradient(ConstVectorRef x, VectorRef grad)
{
    const double cs = std::cos(x[0] + x[1]);
    const double d = x[0] - x[1];
    grad << cs + 2.0 * d - 1.5,
            cs - 2.0 * d + 2.5;
}

void Hs005::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // ∇²f = −sin(x₀ + x₁) [1 1; 1 1] + 2 [1 −1; −1 1]; pattern order (0,0), (1,0), (1,1).
    const double sn = std::sin(x[0] + x[1]);
    values << sigma * (2.0 - sn),
              sigma * (-2.0 - sn),
              sigma * (2.0 - sn);
}

} // namespace sinew
