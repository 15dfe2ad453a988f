#include "sinew/mpm/grid_velocity_nlp.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/bucket_loops.hpp"
#include "sinew/mpm/transfers.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace sinew {
namespace {

int power(int base, int exponent)
{
    int result = 1;
    for (int k = 0; k < exponent; ++k)
        result *= base;
    return result;
}

} // namespace

template <int Dim>
GridVelocityNlp<Dim>::GridVelocityNlp(const Particles<Dim>& particles,
                                      const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                      const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout,
                                      const MpmStepSettings<Dim>& settings)
    : GridVelocityNlp(particles, models,
                      GridVelocityMap<Dim>(particles, grid, settings, GridVelocityMap<Dim>::Predictor::momentum_and_gravity),
                      layout, settings.time_step)
{
}

template <int Dim>
GridVelocityNlp<Dim>::GridVelocityNlp(const Particles<Dim>& particles,
                                      const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                      GridVelocityMap<Dim> map, const ParticleBuckets<Dim>& layout, double time_step,
                                      LinearVelocityRows rows)
    : particles_(particles), models_(models), map_(std::move(map)), layout_(layout), time_step_(time_step),
      rows_(std::move(rows)), variables_(map_.variables()), stencil_nodes_(map_.stencil_nodes())
{
    if (static_cast<int>(layout.order.size()) != particles.size())
        throw std::invalid_argument("GridVelocityNlp: a layout of " + std::to_string(layout.order.size()) +
                                    " particles for " + std::to_string(particles.size()));
    if (rows_.rows() > 0 && (rows_.B.cols() != variables_ || rows_.rhs.size() != rows_.B.rows()))
        throw std::invalid_argument("GridVelocityNlp: constraint rows of " + std::to_string(rows_.B.cols()) +
                                    " columns for " + std::to_string(variables_) + " unknowns");
    if (!(time_step_ > 0.0) || !std::isfinite(time_step_))
        throw InputError("the implicit MPM step needs a finite time step > 0, not " + std::to_string(time_step_));
    for (int p = 0; p < particles.size(); ++p) {
        const int material = particles.material[static_cast<std::size_t>(p)];
        if (material < 0 || material >= static_cast<int>(models.size()) || !models[static_cast<std::size_t>(material)])
            throw InputError("particle " + std::to_string(p) + " has material " + std::to_string(material) +
                             ", which has no model (" + std::to_string(models.size()) + " given)");
    }
    int width = 1;
    while (power(width, Dim) < stencil_nodes_)
        ++width;
    offset_width_ = 2 * width - 1;
    velocities_.assign(static_cast<std::size_t>(nodes()), NodeVector::Zero());
    build_pattern();
    build_jacobian_pattern();
}

template <int Dim>
int GridVelocityNlp<Dim>::table_entry(int a, int b) const
{
    const int reach = (offset_width_ - 1) / 2;
    int linear = 0;
    for (int d = 0; d < Dim; ++d)
        linear = linear * offset_width_ + (map_.index(b)[d] - map_.index(a)[d] + reach);
    return a * power(offset_width_, Dim) + linear;
}

template <int Dim>
void GridVelocityNlp<Dim>::build_pattern()
{
    // Mark every coupled pair a ≥ b with its b; then number the blocks by a, then offset.
    constexpr int kUnmarked = -1;
    const int offsets = power(offset_width_, Dim);
    std::vector<int> partner(static_cast<std::size_t>(nodes()) * static_cast<std::size_t>(offsets), kUnmarked);
    for (int a = 0; a < nodes(); ++a)
        partner[static_cast<std::size_t>(table_entry(a, a))] = a;
    for (int p = 0; p < particles_.size(); ++p) {
        const Coupling* c = map_.couplings(p);
        for (int s = 0; s < stencil_nodes_; ++s)
            for (int t = 0; t < stencil_nodes_; ++t)
                if (c[s].node >= 0 && c[t].node >= 0 && c[s].node > c[t].node)
                    partner[static_cast<std::size_t>(table_entry(c[s].node, c[t].node))] = c[t].node;
    }
    block_table_.assign(partner.size(), -1);
    pattern_ = SparsityPattern();
    for (int a = 0; a < nodes(); ++a) {
        for (int o = 0; o < offsets; ++o) {
            const auto entry = static_cast<std::size_t>(a) * static_cast<std::size_t>(offsets) + static_cast<std::size_t>(o);
            const int b = partner[entry];
            if (b == kUnmarked || free_components(a) == 0 || free_components(b) == 0)
                continue;
            block_table_[entry] = pattern_.nonzeros();
            const int row0 = map_.first_variable(a);
            const int col0 = map_.first_variable(b);
            for (int n = 0; n < free_components(a); ++n)
                for (int m = 0; m < (a == b ? n + 1 : free_components(b)); ++m)
                    pattern_.add(row0 + n, col0 + m);
        }
    }
}

template <int Dim>
void GridVelocityNlp<Dim>::add_block(int a, int b, const Matrix& H_ab, VectorRef values) const
{
    const int start = block_table_[static_cast<std::size_t>(table_entry(a, b))];
    if (start < 0)
        return;  // a node held at v_b: no unknowns
    const auto& Ba = map_.frame(a).basis;
    const auto& Bb = map_.frame(b).basis;
    // B_aᵀ H_ab B_b in storage of at most Dim × Dim on the stack: no heap
    // allocation for each of a particle's 27·28/2 blocks.
    using Reduced = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, Dim, Dim>;
    const Reduced left = Ba.transpose() * H_ab;
    const Reduced reduced = left * Bb;
    int k = start;
    for (int n = 0; n < reduced.rows(); ++n)
        for (int m = 0; m < (a == b ? n + 1 : reduced.cols()); ++m)
            values[k++] += reduced(n, m);
}

template <int Dim>
Eigen::VectorXd GridVelocityNlp<Dim>::starting_point() const
{
    return map_.predictor();
}

template <int Dim>
void GridVelocityNlp<Dim>::update_velocities(ConstVectorRef y)
{
    for (int k = 0; k < nodes(); ++k)
        velocities_[static_cast<std::size_t>(k)] = velocity(k, y);
}

template <int Dim>
typename GridVelocityNlp<Dim>::Matrix GridVelocityNlp<Dim>::deformation_at_velocities(int particle) const
{
    const auto i = static_cast<std::size_t>(particle);
    Matrix F = particles_.F[i];
    const Coupling* c = map_.couplings(particle);
    for (int t = 0; t < stencil_nodes_; ++t)
        if (c[t].node >= 0)
            F += time_step_ * velocities_[static_cast<std::size_t>(c[t].node)] * c[t].b.transpose();  // F = Fⁿ + Δt Σ v_i b_ipᵀ
    return F;
}

template <int Dim>
typename GridVelocityNlp<Dim>::Matrix GridVelocityNlp<Dim>::deformation(int particle, ConstVectorRef y) const
{
    const auto i = static_cast<std::size_t>(particle);
    Matrix F = particles_.F[i];
    const Coupling* c = map_.couplings(particle);
    for (int t = 0; t < stencil_nodes_; ++t)
        if (c[t].node >= 0)
            F += time_step_ * velocity(c[t].node, y) * c[t].b.transpose();
    return F;
}

template <int Dim>
double GridVelocityNlp<Dim>::objective(ConstVectorRef y)
{
    update_velocities(y);
    double E = 0.0;
    for (int k = 0; k < nodes(); ++k) {
        const auto i = static_cast<std::size_t>(k);
        E += 0.5 * map_.mass(k) * (velocities_[i] - map_.target(k)).squaredNorm();  // ½ m ‖v − v*‖²
    }
    for (int p = 0; p < particles_.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const double psi = models_[static_cast<std::size_t>(particles_.material[i])]->energy(deformation_at_velocities(p),
                                                                                           particles_.point[i]);
        if (!std::isfinite(psi))
            return kInfinity;
        E += particles_.volume[i] * psi;  // V_p⁰ ψ(F_p(v))
    }
    return E;
}

template <int Dim>
void GridVelocityNlp<Dim>::gradient(ConstVectorRef y, VectorRef grad)
{
    update_velocities(y);
    std::vector<NodeVector> gradient_v(static_cast<std::size_t>(nodes()));
    for (int k = 0; k < nodes(); ++k) {
        const auto i = static_cast<std::size_t>(k);
        gradient_v[i] = map_.mass(k) * (velocities_[i] - map_.target(k));  // m (v − v*)
    }
    for (int p = 0; p < particles_.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        Matrix P;
        models_[static_cast<std::size_t>(particles_.material[i])]->evaluate(deformation_at_velocities(p),
                                                                            particles_.point[i], &P, nullptr,
                                                                            Projection::none);
        const Matrix scaled = time_step_ * particles_.volume[i] * P;  // Δt V_p⁰ P
        const Coupling* c = map_.couplings(p);
        for (int t = 0; t < stencil_nodes_; ++t)
            if (c[t].node >= 0)
                gradient_v[static_cast<std::size_t>(c[t].node)] += scaled * c[t].b;  // Δt V_p⁰ P b_ip
    }
    for (int k = 0; k < nodes(); ++k) {
        const auto i = static_cast<std::size_t>(k);
        const auto& basis = map_.frame(k).basis;
        if (basis.cols() > 0)
            grad.segment(map_.first_variable(k), basis.cols()) = basis.transpose() * gradient_v[i];  // Bᵀ ∂E/∂v
    }
}

template <int Dim>
void GridVelocityNlp<Dim>::assemble_hessian(ConstVectorRef y, double sigma, Projection projection, VectorRef values)
{
    using Lifted = Eigen::Matrix<double, Dim * Dim, Dim>;
    update_velocities(y);
    values.setZero();
    for (int a = 0; a < nodes(); ++a)
        add_block(a, a, sigma * map_.mass(a) * Matrix::Identity(), values);  // m_i I
    // The buckets of one colour reach disjoint nodes, so their particles add
    // into disjoint blocks of the Hessian.
    for_each_bucket_by_colour(layout_, [&](const typename ParticleBuckets<Dim>::Bucket& bucket) {
        std::vector<Lifted> lifted(static_cast<std::size_t>(stencil_nodes_));
        for (int j = bucket.first; j < bucket.last; ++j)
            add_particle_hessian(layout_.order[static_cast<std::size_t>(j)], sigma, projection, lifted, values);
    });
}

template <int Dim>
void GridVelocityNlp<Dim>::add_particle_hessian(int p, double sigma, Projection projection,
                                                std::vector<Eigen::Matrix<double, Dim * Dim, Dim>>& lifted,
                                                VectorRef values) const
{
    using Stiffness = typename ConstitutiveModel<Dim, Dim>::Stiffness;
    const auto i = static_cast<std::size_t>(p);
    Stiffness K;
    models_[static_cast<std::size_t>(particles_.material[i])]->evaluate(deformation_at_velocities(p), particles_.point[i],
                                                                        nullptr, &K, projection);
    const double scale = sigma * time_step_ * time_step_ * particles_.volume[i];  // σ Δt² V_p⁰
    const Coupling* c = map_.couplings(p);
    for (int t = 0; t < stencil_nodes_; ++t) {
        // (K J_t)(:, col) = Σ_l K(:, col + D l) b_t,l
        auto& KJ = lifted[static_cast<std::size_t>(t)];
        KJ.setZero();
        for (int col = 0; col < Dim; ++col)
            for (int l = 0; l < Dim; ++l)
                KJ.col(col) += c[t].b[l] * K.col(col + Dim * l);
    }
    for (int s = 0; s < stencil_nodes_; ++s) {
        for (int t = 0; t < stencil_nodes_; ++t) {
            if (c[s].node < 0 || c[t].node < 0 || c[s].node < c[t].node)
                continue;
            // (J_sᵀ K J_t)(n, col) = Σ_l b_s,l (K J_t)(n + D l, col)
            const auto& KJ = lifted[static_cast<std::size_t>(t)];
            Matrix H = Matrix::Zero();
            for (int l = 0; l < Dim; ++l)
                H += c[s].b[l] * KJ.template middleRows<Dim>(Dim * l);
            add_block(c[s].node, c[t].node, scale * H, values);
        }
    }
}

template <int Dim>
void GridVelocityNlp<Dim>::build_jacobian_pattern()
{
    jacobian_pattern_ = SparsityPattern();
    for (int r = 0; r < rows_.rows(); ++r)
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows_.B, r); it; ++it)
            jacobian_pattern_.add(r, static_cast<int>(it.col()));
}

template <int Dim>
void GridVelocityNlp<Dim>::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower = rows_.rhs;  // B y = rhs
    upper = rows_.rhs;
}

template <int Dim>
void GridVelocityNlp<Dim>::constraints(ConstVectorRef y, VectorRef c)
{
    c = rows_.B * y;
}

template <int Dim>
void GridVelocityNlp<Dim>::jacobian_values(ConstVectorRef, VectorRef values)
{
    // ∂c/∂y = B, its entries row by row as in the pattern.
    int k = 0;
    for (int r = 0; r < rows_.rows(); ++r)
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows_.B, r); it; ++it)
            values[k++] = it.value();
}

template <int Dim>
void GridVelocityNlp<Dim>::hessian_values(ConstVectorRef y, double sigma, ConstVectorRef, VectorRef values)
{
    assemble_hessian(y, sigma, Projection::none, values);
}

template <int Dim>
void GridVelocityNlp<Dim>::projected_hessian_values(ConstVectorRef y, double sigma, ConstVectorRef, VectorRef values)
{
    assemble_hessian(y, sigma, Projection::clamp, values);
}

template class GridVelocityNlp<2>;
template class GridVelocityNlp<3>;

} // namespace sinew
