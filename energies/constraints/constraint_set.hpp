#pragma once
#include "sinew/core/projection.hpp"
#include "sinew/core/sparsity_pattern.hpp"
#include "sinew/energies/output_arrays.hpp"

#include <Eigen/Core>

#include <string>

namespace sinew {

/// The constraint counterpart of a Potential (DESIGN.md, "Constraints"): a
/// block of constraints l ≤ c(x) ≤ u on the node positions x (node-major,
/// all coordinates), equalities c(x) = 0 unless bounds() says otherwise,
/// with its Jacobian and its contribution Σᵢ λᵢ∇²cᵢ to the Hessian of the
/// Lagrangian. Both patterns are fixed between refresh() calls; evaluations
/// fill values only. Dirichlet conditions as equalities, inextensibility,
/// orthogonality and contact gaps are constraint sets; an NLP composes
/// potentials and constraint sets.
class ConstraintSet {
public:
    using VectorRef = Eigen::Ref<Eigen::VectorXd>;
    using ConstVectorRef = Eigen::Ref<const Eigen::VectorXd>;

    virtual ~ConstraintSet() = default;

    virtual std::string name() const = 0;
    virtual int num_constraints() const = 0;
    /// l and u of each row; default l = u = 0 (equalities). A row with
    /// l < u is an inequality (a contact gap: l = 0, u = ∞).
    virtual void bounds(VectorRef lower, VectorRef upper) const
    {
        lower.setZero();
        upper.setZero();
    }
    /// Between solves, the set may choose its rows anew from the
    /// configuration x (a contact candidate set); true when its rows or
    /// patterns changed, so that the NLP holding it maps them again.
    /// Default: fixed rows.
    virtual bool refresh(ConstVectorRef x)
    {
        static_cast<void>(x);
        return false;
    }
    /// Whether the rows of the last refresh() still stand for every
    /// constraint of the set at x (a contact set: no colliding node outside
    /// its candidates is inside the body); when not, a runner refreshes at x
    /// and solves again. Default: true.
    virtual bool rows_suffice(ConstVectorRef x) const
    {
        static_cast<void>(x);
        return true;
    }
    /// c(x), one entry per constraint of the set.
    virtual void values(ConstVectorRef x, VectorRef c) = 0;
    /// (constraint of the set, coordinate) of each Jacobian entry.
    virtual const SparsityPattern& jacobian_pattern() const = 0;
    virtual void jacobian_values(ConstVectorRef x, VectorRef values) = 0;
    /// Lower triangle (row ≥ col, coordinates) of Σᵢ λᵢ∇²cᵢ; empty when c is linear.
    virtual const SparsityPattern& hessian_pattern() const = 0;
    /// Σᵢ λᵢ∇²cᵢ in hessian_pattern()'s order; with Projection::clamp each
    /// term λᵢ∇²cᵢ is projected onto the PSD cone before the sum.
    virtual void hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection,
                                VectorRef values) = 0;

    /// Adds the set's own point and cell data at x to an output file, with
    /// `multipliers` the λ of its rows (Ipopt's sign convention), or empty
    /// when the solve gave none. Default: none.
    virtual void add_output_data(ConstVectorRef x, ConstVectorRef multipliers, OutputArrays& arrays)
    {
        static_cast<void>(x);
        static_cast<void>(multipliers);
        static_cast<void>(arrays);
    }
};

} // namespace sinew
