#include "sinew/problems/classic/rosenbrock.hpp"

#include "sinew/core/input_error.hpp"

namespace sinew {

Rosenbrock::Rosenbrock(int n) : n_(n)
{
    if (n < 2 || n % 2 != 0)
        throw InputError("rosenbrock: number of variables n = " + std::to_string(n) + " must be even and at least 2");
    // Pair j owns entries 3j (2j, 2j), 3j+1 (2j+1, 2j), 3j+2 (2j+1, 2j+1).
    for (int i = 0; i < n_; i += 2) {
        hessian_pattern_.add(i, i);
        hessian_pattern_.add(i + 1, i);
        hessian_pattern_.add(i + 1, i + 1);
    }
}

std::string Rosenbrock::name() const { return "rosenbrock" + std::to_string(n_); }

Nlp::Vector Rosenbrock::starting_point() const
{
    Vector x(n_);
    for (int i = 0; i < n_; ++i)
        x[i] = (i % 2 == 0) ? -1.2 : 1.0;
    return x;
}

double Rosenbrock::objective(ConstVectorRef x)
{
    double f = 0.0;
    for (int i = 0; i < n_; i += 2) {
        const double r = x[i + 1] - x[i] * x[i];  // x_{2j+1} − x_{2j}²
        const double s = 1.0 - x[i];              // 1 − x_{2j}
        f += 100.0 * r * r + s * s;
    }
    return f;
}

void Rosenbrock::gradient(ConstVectorRef x, VectorRef grad)
{
    for (int i = 0; i < n_; i += 2) {
        const double r = x[i + 1] - x[i] * x[i];
        grad[i] = -400.0 * x[i] * r - 2.0 * (1.0 - x[i]);
        grad[i + 1] = 200.0 * r;
    }
}

void Rosenbrock::hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values)
{
    // ∂²f/∂x_{2j}² = 1200 x_{2j}² − 400 x_{2j+1} + 2, ∂²f/∂x_{2j+1}∂x_{2j} = −400 x_{2j},
    // ∂²f/∂x_{2j+1}² = 200.
    for (int i = 0, k = 0; i < n_; i += 2, k += 3) {
        values[k] = sigma * (1200.0 * x[i] * x[i] - 400.0 * x[i + 1] + 2.0);
        values[k + 1] = sigma * (-400.0 * x[i]);
        values[k + 2] = sigma * 200.0;
    }
}

} // namespace sinew
