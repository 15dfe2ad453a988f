#include "sinew/mpm/particle_buckets.hpp"

#include "sinew/mpm/transfers.hpp"

#include <algorithm>

namespace sinew {
namespace {

/// Whether a stencil based in a block reaches the neighbour at `corner`:
/// along every axis a with bit a set, some particle's base lies within
/// `reach` nodes of the block's upper end (highest[a] + reach ≥ 4).
template <int Dim>
bool reaches(const typename SparseGrid<Dim>::Index& highest, int reach, int corner)
{
    for (int a = 0; a < Dim; ++a)
        if (((corner >> a) & 1) && highest[a] + reach < SparseGrid<Dim>::kBlockWidth)
            return false;
    return true;
}

} // namespace

template <int Dim>
ParticleBuckets<Dim> lay_out_grid(const Particles<Dim>& particles, SplineOrder order, SparseGrid<Dim>& grid)
{
    using Index = typename SparseGrid<Dim>::Index;
    constexpr int kWidth = SparseGrid<Dim>::kBlockWidth;
    grid.clear();
    const int count = particles.size();
    // Each particle's stencil base, in parallel; the lowest particle the grid cannot hold, if any.
    std::vector<Index> base(static_cast<std::size_t>(count));
    int first_outside = count;
#pragma omp parallel for schedule(static) reduction(min : first_outside)
    for (int p = 0; p < count; ++p) {
        const auto& x = particles.x[static_cast<std::size_t>(p)];
        if (in_grid<Dim>(x, grid.dx()))
            base[static_cast<std::size_t>(p)] = stencil_base<Dim>(x, grid.dx(), order);
        else
            first_outside = std::min(first_outside, p);
    }
    if (first_outside < count)
        check_in_grid(particles, first_outside, grid.dx());
    // Each particle's base block, numbered by the grid as first reached: the
    // bases' blocks come first, so a base block's number is its bucket's.
    std::vector<int> bucket_of(static_cast<std::size_t>(count));
    std::vector<Index> highest;  // per bucket, the highest base in the block along each axis (0 … 3)
    Index previous_block = Index::Zero();
    int previous = -1;
    for (int p = 0; p < count; ++p) {
        const Index& node = base[static_cast<std::size_t>(p)];
        const Index block = SparseGrid<Dim>::block_of(node);
        if (previous < 0 || block != previous_block) {
            previous = grid.touch(block * kWidth) / SparseGrid<Dim>::kBlockNodes;
            previous_block = block;
            if (previous == static_cast<int>(highest.size()))
                highest.push_back(Index::Zero());
        }
        bucket_of[static_cast<std::size_t>(p)] = previous;
        Index& top = highest[static_cast<std::size_t>(previous)];
        top = top.cwiseMax(node - block * kWidth);
    }
    ParticleBuckets<Dim> out;
    const int reach = stencil_width(order) - 1;
    const int bucket_count = static_cast<int>(highest.size());
    out.buckets.resize(static_cast<std::size_t>(bucket_count));
    for (int b = 0; b < bucket_count; ++b) {
        auto& bucket = out.buckets[static_cast<std::size_t>(b)];
        bucket.block = SparseGrid<Dim>::block_of(grid.node(b * SparseGrid<Dim>::kBlockNodes));
        for (int corner = 0; corner < ParticleBuckets<Dim>::kCorners; ++corner) {
            Index neighbour = bucket.block;
            for (int a = 0; a < Dim; ++a)
                neighbour[a] += (corner >> a) & 1;
            bucket.neighbours[static_cast<std::size_t>(corner)] =
                reaches<Dim>(highest[static_cast<std::size_t>(b)], reach, corner)
                    ? grid.touch(neighbour * kWidth) / SparseGrid<Dim>::kBlockNodes
                    : -1;
        }
        int colour = 0;
        for (int a = 0; a < Dim; ++a)
            colour |= (bucket.block[a] & 1) << a;
        out.colours[static_cast<std::size_t>(colour)].push_back(b);
    }
    // A stable counting sort of the particles by bucket.
    std::vector<int> start(static_cast<std::size_t>(bucket_count) + 1, 0);
    for (const int b : bucket_of)
        ++start[static_cast<std::size_t>(b) + 1];
    for (std::size_t b = 1; b < start.size(); ++b)
        start[b] += start[b - 1];
    for (int b = 0; b < bucket_count; ++b) {
        out.buckets[static_cast<std::size_t>(b)].first = start[static_cast<std::size_t>(b)];
        out.buckets[static_cast<std::size_t>(b)].last = start[static_cast<std::size_t>(b) + 1];
    }
    out.order.resize(static_cast<std::size_t>(count));
    for (int p = 0; p < count; ++p)
        out.order[static_cast<std::size_t>(start[static_cast<std::size_t>(bucket_of[static_cast<std::size_t>(p)])]++)] = p;
    return out;
}

template <int Dim>
void sort_particles_by_block(Particles<Dim>& particles, double dx, SplineOrder order)
{
    SparseGrid<Dim> grid(dx);
    particles.reorder(lay_out_grid(particles, order, grid).order);
}

template ParticleBuckets<2> lay_out_grid<2>(const Particles<2>&, SplineOrder, SparseGrid<2>&);
template ParticleBuckets<3> lay_out_grid<3>(const Particles<3>&, SplineOrder, SparseGrid<3>&);
template void sort_particles_by_block<2>(Particles<2>&, double, SplineOrder);
template void sort_particles_by_block<3>(Particles<3>&, double, SplineOrder);

} // namespace sinew
