#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/output_arrays.hpp"

#include <Eigen/Core>

#include <string>

namespace sinew {

/// Node tuples whose coordinates a potential's Hessian couples densely, one
/// column per stencil: an element's nodes, or a single node for a node-wise
/// term. A potential whose Hessian is zero has none (zero columns).
using Stencils = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic>;

/// Where each stencil's local Hessian goes in a shared array of nonzero
/// values: column s lists, for the local lower-triangle entries (p, q), p ≥ q,
/// of stencil s in column-major order (q = 0: p = 0 … n−1; q = 1: p = 1 … n−1;
/// …), the index of the global nonzero the entry adds to. The local index of
/// coordinate k of the stencil's node a is p = a·dimension + k, so
/// n = dimension × nodes per stencil. Built once, by HessianPattern::slots.
using StencilSlots = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic>;

/// A scalar potential E(x) of the node positions of a mesh, x node-major
/// (x = [x₀ y₀ z₀ x₁ y₁ z₁ …], DESIGN.md), with its exact gradient and a
/// sparse Hessian whose pattern is fixed at setup.
///
/// Evaluations may use scratch space the potential owns (allocated once), so
/// they are not const: one evaluation at a time per object.
class Potential {
public:
    using VectorRef = Eigen::Ref<Eigen::VectorXd>;
    using ConstVectorRef = Eigen::Ref<const Eigen::VectorXd>;

    virtual ~Potential() = default;

    virtual std::string name() const = 0;
    /// Coordinates per node (2 or 3).
    virtual int dimension() const = 0;
    virtual int num_nodes() const = 0;
    int num_coordinates() const { return dimension() * num_nodes(); }

    /// E(x): +infinity where the potential is undefined (an inverted element
    /// under a model that is not defined there), never NaN.
    virtual double value(ConstVectorRef x) = 0;

    /// gradient += ∇E(x). Meaningful where value(x) is finite.
    virtual void add_gradient(ConstVectorRef x, VectorRef gradient) = 0;

    /// The stencils of the Hessian, fixed at construction.
    virtual const Stencils& hessian_stencils() const = 0;

    /// values[slots(k, s)] += entry k of the lower triangle of stencil s's
    /// local Hessian: ∇²E exactly (Projection::none) or with each local term
    /// projected onto the PSD cone (Projection::clamp), so that the sum is PSD.
    /// `slots` is HessianPattern::slots(hessian_stencils()). No allocation.
    virtual void add_hessian(ConstVectorRef x, Projection projection, const StencilSlots& slots,
                             VectorRef values) = 0;

    /// Adds the potential's own point and cell data at x to an output file
    /// (the elastic potential: activation, damage, fiber, stress norm).
    /// Default: none.
    virtual void add_output_data(ConstVectorRef x, OutputArrays& arrays)
    {
        static_cast<void>(x);
        static_cast<void>(arrays);
    }
};

} // namespace sinew
