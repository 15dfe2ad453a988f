#pragma once
#include "sinew/mpm/bspline_stencil.hpp"
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/sparse_grid.hpp"

#include <array>
#include <vector>

namespace sinew {

/// The particles grouped by the grid block that holds their stencil's first
/// node, so that transfers find a node's slot without a hash lookup and
/// write the grid from several threads with the result of one (docs/mpm.md,
/// "Threads"). A stencil (3 or 4 nodes an axis) starting in block B reaches
/// only B and its upper neighbours B + c, c ∈ {0, 1}^Dim. Blocks whose
/// coordinates have the same parities (a colour: 2^Dim of them) are two
/// blocks apart in some axis, so the buckets of one colour write disjoint
/// nodes and run in parallel; colours run one after the other, and a
/// bucket's particles in increasing index. Every node then sums its
/// particles' contributions in one order, whatever the thread count.
template <int Dim>
struct ParticleBuckets {
    using Index = typename SparseGrid<Dim>::Index;
    static constexpr int kCorners = 1 << Dim;

    struct Bucket {
        Index block;                           ///< block coordinates B
        std::array<int, kCorners> neighbours;  ///< the number of block B + c (bit a of the index is c_a), −1 if absent
        int first = 0, last = 0;               ///< its particles: order[first … last)
    };

    std::vector<int> order;  ///< particle indices, bucket after bucket, increasing within one
    std::vector<Bucket> buckets;
    std::array<std::vector<int>, kCorners> colours;  ///< bucket indices by colour, Σ_a (B_a mod 2) 2^a

    /// The slot of `node` (in the stencil of a particle of `bucket`).
    static int slot(const Bucket& bucket, const Index& node)
    {
        int corner = 0, place = 0;
        for (int a = 0; a < Dim; ++a) {
            const int local = node[a] - bucket.block[a] * SparseGrid<Dim>::kBlockWidth;  // 0 … 7
            corner |= (local >= SparseGrid<Dim>::kBlockWidth ? 1 : 0) << a;
            place = place * SparseGrid<Dim>::kBlockWidth + (local & (SparseGrid<Dim>::kBlockWidth - 1));
        }
        return bucket.neighbours[static_cast<std::size_t>(corner)] * SparseGrid<Dim>::kBlockNodes + place;
    }
};

/// Calls visit(slot, w, d) for every node of a particle's stencil, last axis
/// fastest (the order of BSplineStencil::for_each_offset): the node's slot,
/// its weight w_ip and d = x_i − x_p. The particle lies in `bucket`; x is its
/// position. Per-axis tables make a node's slot and weight a few integer
/// operations and two products (the transfers' inner loop).
template <int Dim, typename Visit>
inline void for_each_stencil_node(const typename ParticleBuckets<Dim>::Bucket& bucket, const BSplineStencil<Dim>& stencil,
                                  const Eigen::Matrix<double, Dim, 1>& x, double dx, const Visit& visit)
{
    constexpr int kWidth = SparseGrid<Dim>::kBlockWidth;
    std::array<std::array<int, BSplineStencil<Dim>::kMaxWidth>, Dim> corner{}, place{};
    std::array<std::array<double, BSplineStencil<Dim>::kMaxWidth>, Dim> distance{};
    for (int a = 0; a < Dim; ++a)
        for (int k = 0; k < stencil.width; ++k) {
            const int node = stencil.base[a] + k;
            const int local = node - bucket.block[a] * kWidth;  // 0 … 7
            corner[a][k] = (local >= kWidth ? 1 : 0) << a;
            place[a][k] = local & (kWidth - 1);
            distance[a][k] = static_cast<double>(node) * dx - x[a];
        }
    const int width = stencil.width;
    if constexpr (Dim == 2) {
        for (int i = 0; i < width; ++i)
            for (int j = 0; j < width; ++j) {
                const int block = bucket.neighbours[static_cast<std::size_t>(corner[0][i] | corner[1][j])];
                visit(block * SparseGrid<Dim>::kBlockNodes + place[0][i] * kWidth + place[1][j],
                      stencil.N[0][i] * stencil.N[1][j], Eigen::Matrix<double, Dim, 1>(distance[0][i], distance[1][j]));
            }
    } else {
        for (int i = 0; i < width; ++i)
            for (int j = 0; j < width; ++j) {
                const double wij = stencil.N[0][i] * stencil.N[1][j];
                for (int k = 0; k < width; ++k) {
                    const int block =
                        bucket.neighbours[static_cast<std::size_t>(corner[0][i] | corner[1][j] | corner[2][k])];
                    visit(block * SparseGrid<Dim>::kBlockNodes + (place[0][i] * kWidth + place[1][j]) * kWidth + place[2][k],
                          wij * stencil.N[2][k],
                          Eigen::Matrix<double, Dim, 1>(distance[0][i], distance[1][j], distance[2][k]));
                }
            }
    }
}

/// Creates, particle after particle, every block the particles' stencils
/// reach (one input, one layout). InputError naming the first particle the
/// grid cannot hold (checked_stencil).
template <int Dim>
void touch_stencil_blocks(const Particles<Dim>& particles, SplineOrder order, SparseGrid<Dim>& grid);

/// The particles' buckets on a grid that holds their stencils' blocks.
template <int Dim>
ParticleBuckets<Dim> bucket_particles(const Particles<Dim>& particles, SplineOrder order, const SparseGrid<Dim>& grid);

/// Calls visit(bucket) for every bucket, the buckets of one colour in
/// parallel (the one thread setting, core/threads.hpp), colour after colour:
/// for passes that add into the grid's nodes.
template <int Dim, typename Visit>
void for_each_bucket_by_colour(const ParticleBuckets<Dim>& buckets, const Visit& visit)
{
    for (const std::vector<int>& colour : buckets.colours) {
        const int count = static_cast<int>(colour.size());
#pragma omp parallel for schedule(dynamic, 1)
        for (int k = 0; k < count; ++k)
            visit(buckets.buckets[static_cast<std::size_t>(colour[static_cast<std::size_t>(k)])]);
    }
}

/// Calls visit(bucket) for every bucket in parallel: for passes that only read the grid.
template <int Dim, typename Visit>
void for_each_bucket(const ParticleBuckets<Dim>& buckets, const Visit& visit)
{
    const int count = static_cast<int>(buckets.buckets.size());
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = 0; k < count; ++k)
        visit(buckets.buckets[static_cast<std::size_t>(k)]);
}

} // namespace sinew
