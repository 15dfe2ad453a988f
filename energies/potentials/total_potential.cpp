#include "sinew/energies/potentials/total_potential.hpp"

#include "sinew/core/input_error.hpp"

#include <limits>
#include <stdexcept>

namespace sinew {
namespace {

std::vector<std::shared_ptr<Potential>> checked_terms(std::vector<std::shared_ptr<Potential>> terms)
{
    if (terms.empty())
        throw InputError("total potential: no terms");
    for (std::size_t t = 0; t < terms.size(); ++t) {
        if (!terms[t])
            throw InputError("total potential: term " + std::to_string(t) + " is null");
        if (terms[t]->dimension() != terms[0]->dimension() || terms[t]->num_nodes() != terms[0]->num_nodes())
            throw InputError("total potential: term '" + terms[t]->name() + "' has " +
                             std::to_string(terms[t]->num_nodes()) + " nodes in " +
                             std::to_string(terms[t]->dimension()) + "D but '" + terms[0]->name() + "' has " +
                             std::to_string(terms[0]->num_nodes()) + " nodes in " +
                             std::to_string(terms[0]->dimension()) + "D");
    }
    return terms;
}

std::vector<const Stencils*> stencil_sets(const std::vector<std::shared_ptr<Potential>>& terms)
{
    std::vector<const Stencils*> sets;
    for (const auto& term : terms)
        sets.push_back(&term->hessian_stencils());
    return sets;
}

} // namespace

TotalPotential::TotalPotential(std::vector<std::shared_ptr<Potential>> terms)
    : terms_(checked_terms(std::move(terms))),
      pattern_(terms_[0]->dimension(), terms_[0]->num_nodes(), stencil_sets(terms_))
{
    for (const auto& term : terms_)
        slots_.push_back(pattern_.slots(term->hessian_stencils()));
}

void TotalPotential::check_size(const char* what, Eigen::Index size, int expected) const
{
    if (size != expected)
        throw std::invalid_argument(std::string("total potential: ") + what + " has size " + std::to_string(size) +
                                    ", expected " + std::to_string(expected));
}

double TotalPotential::value(ConstVectorRef x)
{
    check_size("x", x.size(), num_coordinates());
    constexpr double infinity = std::numeric_limits<double>::infinity();
    double sum = 0.0;
    for (const auto& term : terms_) {
        const double v = term->value(x);
        if (!(v < infinity))  // +∞ or NaN
            return infinity;
        sum += v;
    }
    return sum < infinity ? sum : infinity;
}

void TotalPotential::gradient(ConstVectorRef x, VectorRef gradient)
{
    check_size("x", x.size(), num_coordinates());
    check_size("gradient", gradient.size(), num_coordinates());
    gradient.setZero();
    for (const auto& term : terms_)
        term->add_gradient(x, gradient);
}

void TotalPotential::hessian_values(ConstVectorRef x, Projection projection, VectorRef values)
{
    check_size("x", x.size(), num_coordinates());
    check_size("Hessian values", values.size(), pattern_.nonzeros());
    values.setZero();
    for (std::size_t t = 0; t < terms_.size(); ++t)
        terms_[t]->add_hessian(x, projection, slots_[t], values);
}

} // namespace sinew
