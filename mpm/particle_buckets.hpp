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
/// Built once a step (lay_out_grid) and used by every transfer of the step
/// while the particles stay where they were.
template <int Dim>
struct ParticleBuckets {
    using Index = typename SparseGrid<Dim>::Index;
    static constexpr int kCorners = 1 << Dim;

    struct Bucket {
        Index block;                           ///< block coordinates B
        std::array<int, kCorners> neighbours;  ///< the number of block B + c (bit a of the index is c_a), −1 if no stencil reaches it
        int first = 0, last = 0;               ///< its particles: order[first … last)
    };

    std::vector<int> order;  ///< particle indices, bucket after bucket, increasing within one
    std::vector<Bucket> buckets;
    std::array<std::vector<int>, kCorners> colours;  ///< bucket indices by colour, Σ_a (B_a mod 2) 2^a
};

/// One particle's stencil as per-axis tables, so that a transfer's inner
/// loop costs a few integer operations for a node's slot and sums its
/// products axis by axis (w_ip = Π_a N_a, x_i − x_p = (d_a)_a): along axis
/// a, the k-th node's weight N[a][k], distance d[a][k] = (base_a + k) dx − x_a,
/// and share of the slot (the neighbour block's bit, the place in the block).
template <int Dim>
struct StencilTables {
    int width = 3;
    // Not value-initialized: the constructor fills the first `width` entries
    // of every axis, the only ones read (zeroing them cost the transfers 7 %).
    std::array<std::array<double, BSplineStencil<Dim>::kMaxWidth>, Dim> N, d;
    std::array<std::array<int, BSplineStencil<Dim>::kMaxWidth>, Dim> corner, place;

    /// The tables of the particle at x, in `bucket`, on a grid of spacing dx.
    StencilTables(const typename ParticleBuckets<Dim>::Bucket& bucket, const Eigen::Matrix<double, Dim, 1>& x, double dx,
                  SplineOrder order)
    {
        constexpr int kWidth = SparseGrid<Dim>::kBlockWidth;
        Eigen::Matrix<int, Dim, 1> base;
        if (order == SplineOrder::quadratic) {  // inline: the transfers' hot path
            for (int a = 0; a < Dim; ++a) {
                const double cells = x[a] / dx;
                base[a] = first_node(cells, order);
                quadratic_weights(cells, base[a], N[a].data());
            }
        } else {
            const BSplineStencil<Dim> stencil = bspline_stencil<Dim>(x, dx, order);
            base = stencil.base;
            N = stencil.N;
        }
        width = stencil_width(order);
        for (int a = 0; a < Dim; ++a)
            for (int k = 0; k < width; ++k) {
                const int node = base[a] + k;
                const int local = node - bucket.block[a] * kWidth;  // 0 … 7
                corner[a][k] = (local >= kWidth ? 1 : 0) << a;
                place[a][k] = local & (kWidth - 1);
                d[a][k] = static_cast<double>(node) * dx - x[a];
            }
    }

    /// The slot of the node (i, j) of a 2D stencil.
    int slot(const typename ParticleBuckets<Dim>::Bucket& bucket, int i, int j) const
    {
        constexpr int kWidth = SparseGrid<Dim>::kBlockWidth;
        const int block = bucket.neighbours[static_cast<std::size_t>(corner[0][i] | corner[1][j])];
        return block * SparseGrid<Dim>::kBlockNodes + place[0][i] * kWidth + place[1][j];
    }

    /// The slot of the node (i, j, k) of a 3D stencil.
    int slot(const typename ParticleBuckets<Dim>::Bucket& bucket, int i, int j, int k) const
    {
        constexpr int kWidth = SparseGrid<Dim>::kBlockWidth;
        const int block = bucket.neighbours[static_cast<std::size_t>(corner[0][i] | corner[1][j] | corner[2][k])];
        return block * SparseGrid<Dim>::kBlockNodes + (place[0][i] * kWidth + place[1][j]) * kWidth + place[2][k];
    }
};

/// Clears the grid, creates every block the particles' stencils reach and
/// returns their buckets: the layout of one step. Blocks are numbered in the
/// order the particles first reach them (one input, one layout); a block
/// holding stencil bases is found by a hash lookup only when a particle's
/// differs from the one before it. InputError naming the first particle the
/// grid cannot hold (check_in_grid).
template <int Dim>
ParticleBuckets<Dim> lay_out_grid(const Particles<Dim>& particles, SplineOrder order, SparseGrid<Dim>& grid);

/// Renumbers the particles bucket after bucket, in the order lay_out_grid
/// gives them on a grid of spacing dx, so that a transfer reads a bucket's
/// particles from consecutive memory instead of jumping by rows of a
/// lattice (at 10⁶ particles P2G took 20–25 % less time,
/// docs/benchmarks.md). The order holds while particles stay in their
/// blocks. InputError as lay_out_grid.
template <int Dim>
void sort_particles_by_block(Particles<Dim>& particles, double dx, SplineOrder order);

} // namespace sinew
