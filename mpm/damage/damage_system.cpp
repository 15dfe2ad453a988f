#include "sinew/mpm/damage/damage_system.hpp"

#include <Eigen/LU>

namespace sinew {

template <int Dim>
DamageSystem<Dim>::DamageSystem(const Particles<Dim>& particles, const std::vector<double>& driving, double dt,
                                const DamageGrid<Dim>& grid)
{
    const int slots = grid.nodes.slots();
    rhs_ = Eigen::VectorXd::Zero(slots);
    lumped_ = Eigen::VectorXd::Zero(slots);
    full_ = Eigen::VectorXd::Zero(slots);
    const auto count = static_cast<std::size_t>(particles.size());
    slot_.reserve(count * kNodes);
    gradient_.reserve(count * kNodes);
    diffusion_.resize(count);
    for (std::size_t p = 0; p < count; ++p) {
        const PhaseFieldPoint<Dim>& field = particles.phase_field[p];
        const double V = particles.volume[p] * particles.F[p].determinant();  // V_p = V_p⁰ det F_p
        const double tau = dt / field.eta;                                    // τ_p = Δt/η_p
        diffusion_[p] = V * tau * field.l0 * field.l0;
        for_each_damage_node(particles, grid, static_cast<int>(p), [&](int slot, double w, const Vector& g) {
            const auto i = static_cast<std::size_t>(slot);
            rhs_[slot] += V * (tau * driving[p] + grid.damage[i]) * w;   // c_i
            lumped_[slot] += V * (1.0 + tau * (driving[p] + 1.0)) * w;  // A_ii
            full_[slot] += diffusion_[p] * g.squaredNorm();               // B_ii
            slot_.push_back(slot);
            gradient_.push_back(g);
        });
    }
    full_ += lumped_;
}

template <int Dim>
void DamageSystem<Dim>::multiply(const Eigen::VectorXd& d, Eigen::VectorXd& out) const
{
    out = lumped_.cwiseProduct(d);  // A d
    for (std::size_t p = 0; p < diffusion_.size(); ++p) {
        const std::size_t first = p * kNodes;
        Vector gradient = Vector::Zero();  // ∇d(x_p) = Σ_j d_j ∇w_jp
        for (std::size_t k = first; k < first + kNodes; ++k)
            gradient += d[slot_[k]] * gradient_[k];
        for (std::size_t k = first; k < first + kNodes; ++k)
            out[slot_[k]] += diffusion_[p] * gradient_[k].dot(gradient);  // B d
    }
}

template class DamageSystem<2>;
template class DamageSystem<3>;

} // namespace sinew
