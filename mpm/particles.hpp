#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/damage/phase_field_point.hpp"

#include <Eigen/Core>

#include <type_traits>
#include <vector>

namespace sinew {

/// The material points of MLS-MPM as plain arrays, one entry per particle
/// (structure of arrays; docs/mpm.md): state advanced by the transfers and
/// the step, and what the constitutive models read.
template <int Dim>
struct Particles {
    using Vector = Eigen::Matrix<double, Dim, 1>;
    using Matrix = Eigen::Matrix<double, Dim, Dim>;

    std::vector<Vector> x;            ///< position
    std::vector<Vector> v;            ///< velocity
    std::vector<double> mass;         ///< m_p
    std::vector<double> volume;       ///< rest volume V_p⁰
    std::vector<Matrix> F;            ///< deformation gradient
    /// The MLS velocity gradient Σ_i w_ip v_i (x_i − x_p)ᵀ D_p⁻¹ of the last
    /// grid-to-particle transfer: APIC's affine matrix C_p, and ∇v_p in the
    /// update of F.
    std::vector<Matrix> C;
    std::vector<int> material;                 ///< index into the run's models
    std::vector<MaterialPoint<Dim>> point;    ///< fiber director, activation, damage
    /// AnisoMPM's phase-field data (mpm/damage): empty when the run has no
    /// damage evolution, else one per particle.
    std::vector<PhaseFieldPoint<Dim>> phase_field;

    int size() const { return static_cast<int>(x.size()); }

    /// Appends a particle at rest shape (F = I, C = 0) with default material
    /// data (and a default phase-field point when the particles carry them).
    void add(const Vector& position, const Vector& velocity, double particle_mass, double rest_volume,
             int material_index = 0)
    {
        x.push_back(position);
        v.push_back(velocity);
        mass.push_back(particle_mass);
        volume.push_back(rest_volume);
        F.push_back(Matrix::Identity());
        C.push_back(Matrix::Zero());
        material.push_back(material_index);
        point.emplace_back();
        if (!phase_field.empty())
            phase_field.emplace_back();
    }

    /// Renumbers the particles: particle k becomes the one that was
    /// order[k] (order a permutation of 0 … size − 1). Every array above.
    void reorder(const std::vector<int>& order)
    {
        auto permuted = [&order](auto& values) {
            std::decay_t<decltype(values)> out;
            out.reserve(values.size());
            for (const int k : order)
                out.push_back(values[static_cast<std::size_t>(k)]);
            values.swap(out);
        };
        permuted(x);
        permuted(v);
        permuted(mass);
        permuted(volume);
        permuted(F);
        permuted(C);
        permuted(material);
        permuted(point);
        if (!phase_field.empty())
            permuted(phase_field);
    }
};

} // namespace sinew
