#pragma once
#include "sinew/energies/potentials/element_model.hpp"
#include "sinew/energies/potentials/potential.hpp"
#include "sinew/mesh/mesh.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sinew {

namespace detail {
class ElasticElements;
}

/// The hyperelastic energy of a simplicial mesh (seed 000 §4):
///
///     E(x) = Σ_e W_e ψ_g(e)(F_e; a_e, α_e, d_e),    F_e = Ds(x)·Dm⁻¹     (§4.1)
///
/// W_e the rest measure (volume of a tet, area of a triangle), ψ_g the model
/// of the element's group, and the element's material point: fiber a_e,
/// activation α_e, damage d_e. Dm⁻¹ and W_e are computed once here.
/// Gradient and Hessian follow from P and ∂P/∂F by the chain rule through
/// ∂F/∂x (simplex_kinematics.hpp); the gradient is minus the finite-volume
/// forces G = P·Bm of §4.4.
///
/// Element kinds: tets (F 3×3), triangles in 2D (F 2×2), triangles in 3D
/// (F 3×2): these are written in an orthonormal in-plane rest frame
/// (membrane_rest_frame: e₁ along the first edge, e₂ = n̂ × e₁), in which Dm is
/// 2×2; their fibers are 2-vectors in that frame.
///
/// Evaluation is parallel (OpenMP) and deterministic: element energies go to
/// a per-element buffer summed in element order; gradients and Hessians are
/// added block by block in a fixed schedule (assembly_schedule.hpp), so every
/// entry receives the same contributions in the same order for any number of
/// threads.
class ElasticPotential final : public Potential {
public:
    /// `group_models[g]` is the model of the elements with
    /// mesh.element_groups[e] == g. Fibers come from mesh.element_fibers
    /// (material_dimension rows; for triangles in 3D also 3 rows, a direction
    /// in space projected onto the rest plane), x̂ where it is empty;
    /// activation and damage start at 0.
    ///
    /// InputError naming what is wrong: inconsistent mesh arrays, a
    /// degenerate element, a group index out of range, a model count that
    /// differs from the mesh's group count, a null model, a model whose F
    /// shape is not that of the elements, an invalid fiber.
    ElasticPotential(const Mesh& mesh, std::vector<ElementModel> group_models);
    ~ElasticPotential() override;

    std::string name() const override { return "elastic"; }
    int dimension() const override;
    int num_nodes() const override;
    ElementKind kind() const { return kind_; }
    int num_elements() const;

    double value(ConstVectorRef x) override;
    void add_gradient(ConstVectorRef x, VectorRef gradient) override;
    /// The elements (one stencil per element, its nodes in mesh order).
    const Stencils& hessian_stencils() const override;
    void add_hessian(ConstVectorRef x, Projection projection, const StencilSlots& slots, VectorRef values) override;

    /// Adds ∂(∇E)/∂α for one activation α shared by `elements` (a muscle,
    /// seed 000 eq. 4: the force is linear in α, so this is −f_i of §2.1):
    /// Σ_e W_e ∂P_e/∂α · Dm⁻ᵀ on each element's nodes (simplex_kinematics.hpp).
    /// InputError for an element out of range or vectors of the wrong size.
    void add_activation_gradient(ConstVectorRef x, const std::vector<int>& elements, VectorRef gradient) const;
    /// ‖P(F_e)‖_F per element (Pa for tets and 2D triangles, N/m for
    /// membranes): the stress invariant the VTU output shows.
    Eigen::VectorXd stress_norms(ConstVectorRef x) const;
    /// Cell data: "activation", "damage", "fiber" (material space; for
    /// membranes the element's rest frame) and "stress_norm" (‖P‖_F).
    void add_output_data(ConstVectorRef x, OutputArrays& arrays) override;
    /// Fiber a₀ of an element in material space, normalized here: a
    /// material_dimension vector, or for triangles in 3D also a direction in
    /// space, projected onto the element's rest plane. InputError for a zero,
    /// non-finite or (membranes) plane-normal fiber, or a bad element index.
    void set_fiber(int element, const Eigen::VectorXd& fiber);
    /// Muscle activation α ∈ [0, 1]; InputError outside.
    void set_activation(int element, double activation);
    /// Damage d ∈ [0, 1]; InputError outside.
    void set_damage(int element, double damage);

    Eigen::VectorXd fiber(int element) const;
    double activation(int element) const;
    double damage(int element) const;

    /// Colors and blocks of the deterministic parallel assembly.
    int num_colors() const;
    int num_blocks() const;

private:
    ElementKind kind_;
    std::unique_ptr<detail::ElasticElements> elements_;
};

} // namespace sinew
