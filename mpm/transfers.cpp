#include "sinew/mpm/transfers.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/bucket_loops.hpp"

#include <cmath>
#include <sstream>
#include <type_traits>

namespace sinew {

template <int Dim>
bool in_grid(const Eigen::Matrix<double, Dim, 1>& x, double dx)
{
    const double reach = static_cast<double>(SparseGrid<Dim>::kMaxIndex - 4) * dx;
    return x.allFinite() && x.cwiseAbs().maxCoeff() < reach;
}

template <int Dim>
void check_in_grid(const Particles<Dim>& particles, int p, double dx)
{
    const auto& x = particles.x[static_cast<std::size_t>(p)];
    if (!in_grid<Dim>(x, dx)) {
        const double reach = static_cast<double>(SparseGrid<Dim>::kMaxIndex - 4) * dx;
        std::ostringstream message;
        message << "particle " << p << " at (" << x.transpose() << ") lies outside the grid's domain, |x| < "
                << reach << " in each axis (2^20 cells of dx = " << dx << ")";
        throw InputError(message.str());
    }
}

template <int Dim>
BSplineStencil<Dim> checked_stencil(const Particles<Dim>& particles, int p, double dx, SplineOrder order)
{
    check_in_grid(particles, p, dx);
    return bspline_stencil<Dim>(particles.x[static_cast<std::size_t>(p)], dx, order);
}

namespace {

/// A node's mass and momentum together, (m, m v): one vector operation a
/// node in the scatter (four doubles in 3D, AVX's width).
template <int Dim>
using MassMomentum = typename decltype(SparseGrid<Dim>::StepBuffers::mass_momentum)::value_type;

/// A node's velocity as the gather reads it, padded to four doubles in 3D.
template <int Dim>
using PackedVelocity = typename decltype(SparseGrid<Dim>::StepBuffers::velocity)::value_type;

/// The weights and distances of a stencil's tables as local arrays of a
/// width known when compiling: the loops unroll, and the stores into the
/// grid cannot be taken to change them (no reloads).
template <int Dim, int Width>
struct LocalTables {
    double N[Dim][Width], d[Dim][Width];

    explicit LocalTables(const StencilTables<Dim>& t)
    {
        for (int a = 0; a < Dim; ++a)
            for (int k = 0; k < Width; ++k) {
                N[a][k] = t.N[a][k];
                d[a][k] = t.d[a][k];
            }
    }
};

/// Adds one particle to its stencil's nodes, q_i += w (m, m v_p + A d) with
/// A = m C_p + S_p and d = x_i − x_p summed axis by axis; with `plain`
/// (PIC/FLIP) also w m v_p into velocity_transferred, a momentum until
/// particles_to_grid divides it.
template <int Dim, bool plain, int Width>
void scatter(const typename ParticleBuckets<Dim>::Bucket& bucket, const StencilTables<Dim>& t, double m,
             const Eigen::Matrix<double, Dim, 1>& mv, const Eigen::Matrix<double, Dim, Dim>& A,
             MassMomentum<Dim>* q, SparseGrid<Dim>& grid)
{
    using Packed = MassMomentum<Dim>;
    const LocalTables<Dim, Width> local(t);
    Packed start, column[Dim];  // (m, m v_p) and (0, A e_c)
    start << m, mv;
    for (int c = 0; c < Dim; ++c)
        column[c] << 0.0, A.col(c);
    auto add = [&](int slot, double w, const Packed& value) {
        const auto s = static_cast<std::size_t>(slot);
        q[s] += w * value;
        if constexpr (plain)
            grid.velocity_transferred[s] += w * mv;
    };
    for (int i = 0; i < Width; ++i) {
        const Packed along_0 = start + column[0] * local.d[0][i];
        for (int j = 0; j < Width; ++j) {
            const double wij = local.N[0][i] * local.N[1][j];
            const Packed along_1 = along_0 + column[1] * local.d[1][j];
            if constexpr (Dim == 2) {
                add(t.slot(bucket, i, j), wij, along_1);
            } else {
                for (int k = 0; k < Width; ++k)
                    add(t.slot(bucket, i, j, k), wij * local.N[2][k], along_1 + column[2] * local.d[2][k]);
            }
        }
    }
}

/// One particle's sums over its stencil: Σ w v_i, B = Σ w v_i dᵀ and, with
/// `flip`, Σ w (v_i − v_i transferred), summed axis by axis.
template <int Dim>
struct Gathered {
    Eigen::Matrix<double, Dim, 1> velocity = Eigen::Matrix<double, Dim, 1>::Zero();
    Eigen::Matrix<double, Dim, 1> increment = Eigen::Matrix<double, Dim, 1>::Zero();
    Eigen::Matrix<double, Dim, Dim> B = Eigen::Matrix<double, Dim, Dim>::Zero();
};

template <int Dim, bool flip, int Width>
Gathered<Dim> gather(const typename ParticleBuckets<Dim>::Bucket& bucket, const StencilTables<Dim>& t,
                     const PackedVelocity<Dim>* velocity, const SparseGrid<Dim>& grid)
{
    using Packed = PackedVelocity<Dim>;
    const LocalTables<Dim, Width> local(t);
    Packed sum = Packed::Zero(), moment[Dim];  // Σ w v, and Σ w v d_c by axis c
    for (int c = 0; c < Dim; ++c)
        moment[c].setZero();
    Gathered<Dim> out;
    for (int i = 0; i < Width; ++i) {
        Packed sum_0 = Packed::Zero();
        for (int j = 0; j < Width; ++j) {
            const double wij = local.N[0][i] * local.N[1][j];
            Packed sum_1 = Packed::Zero();
            auto add = [&](int slot, double w) {
                const auto s = static_cast<std::size_t>(slot);
                const Packed wv = w * velocity[s];
                sum_1 += wv;
                if constexpr (flip)
                    out.increment += wv.template head<Dim>() - w * grid.velocity_transferred[s];
                return wv;
            };
            if constexpr (Dim == 2) {
                add(t.slot(bucket, i, j), wij);
            } else {
                for (int k = 0; k < Width; ++k)
                    moment[2] += local.d[2][k] * add(t.slot(bucket, i, j, k), wij * local.N[2][k]);
            }
            moment[1] += local.d[1][j] * sum_1;
            sum_0 += sum_1;
        }
        moment[0] += local.d[0][i] * sum_0;
        sum += sum_0;
    }
    out.velocity = sum.template head<Dim>();
    for (int c = 0; c < Dim; ++c)
        out.B.col(c) = moment[c].template head<Dim>();
    return out;
}

/// How many particles ahead a transfer asks for their data: about a memory
/// latency's worth of one particle's work.
constexpr int kPrefetchAhead = 4;

/// Asks the cache for entry i of every array (its first and last byte: a
/// 3×3 matrix spans two cache lines): transfers visit the particles bucket
/// after bucket, which jumps through their arrays.
template <typename... Arrays>
void prefetch_entry(std::size_t i, const Arrays&... arrays)
{
    auto fetch = [i](const auto& array) {
        const char* entry = reinterpret_cast<const char*>(&array[i]);
        __builtin_prefetch(entry);
        __builtin_prefetch(entry + sizeof(array[i]) - 1);
    };
    (fetch(arrays), ...);
}

/// scatter or gather with the flag and the stencil width as template
/// arguments: call(std::integral_constant<bool, flag>, std::integral_constant<int, width>).
template <typename Call>
auto with_constants(bool flag, int width, const Call& call)
{
    using Three = std::integral_constant<int, 3>;
    using Four = std::integral_constant<int, 4>;
    if (flag)
        return width == 3 ? call(std::true_type{}, Three{}) : call(std::true_type{}, Four{});
    return width == 3 ? call(std::false_type{}, Three{}) : call(std::false_type{}, Four{});
}

} // namespace

template <int Dim>
ParticleBuckets<Dim> particles_to_grid(const Particles<Dim>& particles, const TransferSettings& settings,
                                       SparseGrid<Dim>& grid, const std::vector<typename Particles<Dim>::Matrix>* impulses)
{
    using Vector = typename SparseGrid<Dim>::Vector;
    using Matrix = typename Particles<Dim>::Matrix;
    using Bucket = typename ParticleBuckets<Dim>::Bucket;
    ParticleBuckets<Dim> layout = lay_out_grid(particles, settings.order, grid);
    const double dx = grid.dx();
    const bool affine = settings.scheme == TransferScheme::apic;
    const bool flip = settings.scheme == TransferScheme::pic_flip;
    const int slots = grid.slots();
    std::vector<MassMomentum<Dim>>& q = grid.buffers.mass_momentum;
    q.resize(static_cast<std::size_t>(slots));
#pragma omp parallel for schedule(static)
    for (int slot = 0; slot < slots; ++slot)
        q[static_cast<std::size_t>(slot)].setZero();
    for_each_bucket_by_colour(layout, [&](const Bucket& bucket) {
        for (int j = bucket.first; j < bucket.last; ++j) {
            const auto i = static_cast<std::size_t>(layout.order[static_cast<std::size_t>(j)]);
            if (j + kPrefetchAhead < bucket.last) {
                const auto next = static_cast<std::size_t>(layout.order[static_cast<std::size_t>(j + kPrefetchAhead)]);
                prefetch_entry(next, particles.x, particles.v, particles.C, particles.mass);
                if (impulses)
                    prefetch_entry(next, *impulses);
            }
            const double m = particles.mass[i];
            Matrix A = affine ? Matrix(m * particles.C[i]) : Matrix::Zero();  // m_p C_p + S_p
            if (impulses)
                A += (*impulses)[i];
            const StencilTables<Dim> tables(bucket, particles.x[i], dx, settings.order);
            const Vector mv = m * particles.v[i];
            with_constants(flip, tables.width, [&](auto plain, auto width) {
                scatter<Dim, decltype(plain)::value, decltype(width)::value>(bucket, tables, m, mv, A, q.data(), grid);
            });
        }
    });
#pragma omp parallel for schedule(static)
    for (int slot = 0; slot < slots; ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        const double m = q[s][0];
        grid.mass[s] = m;
        grid.momentum[s] = q[s].template tail<Dim>();
        grid.velocity[s] = m > 0.0 ? Vector(grid.momentum[s] / m) : Vector::Zero();
        if (flip)
            grid.velocity_transferred[s] = m > 0.0 ? Vector(grid.velocity_transferred[s] / m) : Vector::Zero();
    }
    return layout;
}

namespace {

/// grid_to_particles, and with `advection` (a step h) x_p ← x_p + h v_p and
/// F_p ← (I + h C_p) F_p while the particle's data is at hand.
template <int Dim>
void gather_to_particles(const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout, const TransferSettings& settings,
                         const double* advection, Particles<Dim>& particles)
{
    using Vector = typename SparseGrid<Dim>::Vector;
    using Matrix = typename Particles<Dim>::Matrix;
    using Bucket = typename ParticleBuckets<Dim>::Bucket;
    const double dx = grid.dx();
    const double inverse_D = 1.0 / (apic_inertia_factor(settings.order) * dx * dx);  // D_p⁻¹ = I/(σ dx²)
    const bool flip = settings.scheme == TransferScheme::pic_flip;
    const int slots = grid.slots();
    std::vector<PackedVelocity<Dim>>& velocity = grid.buffers.velocity;
    velocity.resize(static_cast<std::size_t>(slots));
#pragma omp parallel for schedule(static)
    for (int slot = 0; slot < slots; ++slot) {
        PackedVelocity<Dim>& packed = velocity[static_cast<std::size_t>(slot)];
        packed.setZero();
        packed.template head<Dim>() = grid.velocity[static_cast<std::size_t>(slot)];
    }
    for_each_bucket(layout, [&](const Bucket& bucket) {
        for (int j = bucket.first; j < bucket.last; ++j) {
            const auto i = static_cast<std::size_t>(layout.order[static_cast<std::size_t>(j)]);
            if (j + kPrefetchAhead < bucket.last)
                prefetch_entry(static_cast<std::size_t>(layout.order[static_cast<std::size_t>(j + kPrefetchAhead)]), particles.x, particles.v,
                               particles.C, particles.F);
            const StencilTables<Dim> tables(bucket, particles.x[i], dx, settings.order);
            const Gathered<Dim> sums = with_constants(flip, tables.width, [&](auto with_flip, auto width) {
                return gather<Dim, decltype(with_flip)::value, decltype(width)::value>(bucket, tables, velocity.data(), grid);
            });
            particles.C[i] = sums.B * inverse_D;
            particles.v[i] = flip ? Vector((1.0 - settings.flip_ratio) * sums.velocity +
                                           settings.flip_ratio * (particles.v[i] + sums.increment))
                                  : sums.velocity;
            if (advection) {
                const double h = *advection;
                particles.x[i] += h * particles.v[i];
                particles.F[i] = (Matrix::Identity() + h * particles.C[i]) * particles.F[i];  // Fⁿ⁺¹ = (I + Δt ∇v) Fⁿ
            }
        }
    });
}

} // namespace

template <int Dim>
void grid_to_particles(const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout, const TransferSettings& settings,
                       Particles<Dim>& particles)
{
    gather_to_particles(grid, layout, settings, nullptr, particles);
}

template <int Dim>
void grid_to_particles_advected(const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout,
                                const TransferSettings& settings, double time_step, Particles<Dim>& particles)
{
    gather_to_particles(grid, layout, settings, &time_step, particles);
}

template bool in_grid<2>(const Eigen::Vector2d&, double);
template bool in_grid<3>(const Eigen::Vector3d&, double);
template void check_in_grid<2>(const Particles<2>&, int, double);
template void check_in_grid<3>(const Particles<3>&, int, double);
template BSplineStencil<2> checked_stencil<2>(const Particles<2>&, int, double, SplineOrder);
template BSplineStencil<3> checked_stencil<3>(const Particles<3>&, int, double, SplineOrder);
template ParticleBuckets<2> particles_to_grid<2>(const Particles<2>&, const TransferSettings&, SparseGrid<2>&,
                                                 const std::vector<Eigen::Matrix2d>*);
template ParticleBuckets<3> particles_to_grid<3>(const Particles<3>&, const TransferSettings&, SparseGrid<3>&,
                                                 const std::vector<Eigen::Matrix3d>*);
template void grid_to_particles<2>(const SparseGrid<2>&, const ParticleBuckets<2>&, const TransferSettings&, Particles<2>&);
template void grid_to_particles<3>(const SparseGrid<3>&, const ParticleBuckets<3>&, const TransferSettings&, Particles<3>&);
template void grid_to_particles_advected<2>(const SparseGrid<2>&, const ParticleBuckets<2>&, const TransferSettings&, double,
                                            Particles<2>&);
template void grid_to_particles_advected<3>(const SparseGrid<3>&, const ParticleBuckets<3>&, const TransferSettings&, double,
                                            Particles<3>&);

} // namespace sinew
