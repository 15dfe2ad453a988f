#include "sinew/mpm/grid_velocity_map.hpp"

#include "sinew/mpm/bspline_stencil.hpp"
#include "sinew/mpm/transfers.hpp"

namespace sinew {

template <int Dim>
GridVelocityMap<Dim>::GridVelocityMap(const Particles<Dim>& particles, const SparseGrid<Dim>& grid,
                                      const MpmStepSettings<Dim>& settings, Predictor predictor)
{
    build_nodes(grid, settings, predictor);
    build_couplings(particles, grid, settings.transfer.order);
}

template <int Dim>
void GridVelocityMap<Dim>::build_nodes(const SparseGrid<Dim>& grid, const MpmStepSettings<Dim>& settings,
                                       Predictor predictor)
{
    for (int slot = 0; slot < grid.slots(); ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        if (!(grid.mass[s] > 0.0))
            continue;
        const NodeVector target = predictor == Predictor::grid_velocity
                                      ? grid.velocity[s]
                                      : NodeVector(grid.momentum[s] / grid.mass[s] + settings.time_step * settings.gravity);  // v* = (m v)/m + Δt g
        slot_.push_back(slot);
        index_.push_back(grid.node(slot));
        mass_.push_back(grid.mass[s]);
        target_.push_back(target);
        frames_.push_back(node_velocity_frame(node_contacts(settings, grid.position(slot), grid.dx()), target));
        first_variable_.push_back(variables_);
        variables_ += static_cast<int>(frames_.back().basis.cols());
    }
}

template <int Dim>
void GridVelocityMap<Dim>::build_couplings(const Particles<Dim>& particles, const SparseGrid<Dim>& grid, SplineOrder order)
{
    int stencil_nodes = 1;
    for (int d = 0; d < Dim; ++d)
        stencil_nodes *= stencil_width(order);
    stencil_nodes_ = stencil_nodes;
    std::vector<int> node_of_slot(static_cast<std::size_t>(grid.slots()), -1);
    for (int k = 0; k < nodes(); ++k)
        node_of_slot[static_cast<std::size_t>(slot(k))] = k;
    const double dx = grid.dx();
    const double inverse_D = 1.0 / (apic_inertia_factor(order) * dx * dx);  // D_p⁻¹ = (σ dx²)⁻¹ I
    couplings_.assign(static_cast<std::size_t>(particles.size()) * static_cast<std::size_t>(stencil_nodes_), {});
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const BSplineStencil<Dim> stencil = checked_stencil(particles, p, dx, order);
        std::size_t k = i * static_cast<std::size_t>(stencil_nodes_);
        stencil.for_each_offset([&](const Index& offset) {
            Coupling& coupling = couplings_[k++];
            const Index node = stencil.base + offset;
            const int found = grid.find(node);
            if (found < 0 || node_of_slot[static_cast<std::size_t>(found)] < 0)
                return;
            coupling.node = node_of_slot[static_cast<std::size_t>(found)];
            // q_ip = w_ip D⁻¹ (x_i − x_p),  b_ip = Fⁿᵀ q_ip
            const NodeVector q = stencil.weight(offset) * inverse_D * (node.template cast<double>() * dx - particles.x[i]);
            coupling.b = particles.F[i].transpose() * q;
        });
    }
}

template <int Dim>
typename GridVelocityMap<Dim>::NodeVector GridVelocityMap<Dim>::velocity(int node,
                                                                         const Eigen::Ref<const Eigen::VectorXd>& y) const
{
    const NodeVelocityFrame<Dim>& f = frame(node);
    if (f.basis.cols() == 0)
        return f.offset;  // held at v_b (an empty B has no data to multiply)
    return f.offset + f.basis * y.segment(first_variable(node), f.basis.cols());  // v = offset + B y
}

template <int Dim>
Eigen::VectorXd GridVelocityMap<Dim>::predictor() const
{
    Eigen::VectorXd y(variables_);
    for (int k = 0; k < nodes(); ++k) {
        const NodeVelocityFrame<Dim>& f = frame(k);
        if (f.basis.cols() > 0)
            y.segment(first_variable(k), f.basis.cols()) = f.basis.transpose() * (target(k) - f.offset);
    }
    return y;
}

template <int Dim>
Eigen::VectorXd GridVelocityMap<Dim>::variable_masses() const
{
    Eigen::VectorXd masses(variables_);
    for (int k = 0; k < nodes(); ++k)
        masses.segment(first_variable(k), free_components(k)).setConstant(mass(k));
    return masses;
}

template <int Dim>
void GridVelocityMap<Dim>::write_velocities(const Eigen::Ref<const Eigen::VectorXd>& y, SparseGrid<Dim>& grid) const
{
    for (int k = 0; k < nodes(); ++k)
        grid.velocity[static_cast<std::size_t>(slot(k))] = velocity(k, y);
}

template class GridVelocityMap<2>;
template class GridVelocityMap<3>;

} // namespace sinew
