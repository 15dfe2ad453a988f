#pragma once
#include "sinew/energies/potentials/hessian_pattern.hpp"
#include "sinew/energies/potentials/potential.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sinew {

/// E(x) = Σ_t E_t(x) over potentials of the same nodes (elastic, gravity,
/// loads, obstacle penalties, …), with one Hessian pattern for the sum built
/// at construction from every term's stencils, and every term's slot table.
///
/// Terms are evaluated and added in the order given, each one
/// deterministically, so value, gradient and Hessian are bitwise the same for
/// any number of threads.
class TotalPotential {
public:
    using VectorRef = Potential::VectorRef;
    using ConstVectorRef = Potential::ConstVectorRef;

    /// InputError when `terms` is empty, holds a null term, or the terms
    /// disagree on dimension or node count (naming the two terms).
    explicit TotalPotential(std::vector<std::shared_ptr<Potential>> terms);

    int dimension() const { return pattern_.dimension(); }
    int num_nodes() const { return pattern_.num_nodes(); }
    int num_coordinates() const { return pattern_.num_coordinates(); }
    const std::vector<std::shared_ptr<Potential>>& terms() const { return terms_; }

    /// Σ E_t(x); +infinity as soon as one term is not finite (never NaN).
    double value(ConstVectorRef x);
    /// ∇E(x), overwriting `gradient`.
    void gradient(ConstVectorRef x, VectorRef gradient);

    const HessianPattern& hessian_pattern() const { return pattern_; }
    /// ∇²E(x), lower triangle in hessian_pattern() order, overwriting
    /// `values`; with Projection::clamp every local term is projected. No
    /// allocation.
    void hessian_values(ConstVectorRef x, Projection projection, VectorRef values);

private:
    void check_size(const char* what, Eigen::Index size, int expected) const;

    std::vector<std::shared_ptr<Potential>> terms_;
    HessianPattern pattern_;
    std::vector<StencilSlots> slots_;
};

} // namespace sinew
