#include "sinew/mpm/particle_buckets.hpp"

#include "sinew/mpm/transfers.hpp"

#include <stdexcept>

namespace sinew {

template <int Dim>
void touch_stencil_blocks(const Particles<Dim>& particles, SplineOrder order, SparseGrid<Dim>& grid)
{
    using Index = typename SparseGrid<Dim>::Index;
    const int reach = stencil_width(order) - 1;
    for (int p = 0; p < particles.size(); ++p) {
        check_in_grid(particles, p, grid.dx());
        const Index base = stencil_base<Dim>(particles.x[static_cast<std::size_t>(p)], grid.dx(), order);
        for (int corner = 0; corner < (1 << Dim); ++corner) {
            Index node = base;
            for (int a = 0; a < Dim; ++a)
                node[a] += (corner >> a) & 1 ? reach : 0;
            grid.touch(node);
        }
    }
}

template <int Dim>
ParticleBuckets<Dim> bucket_particles(const Particles<Dim>& particles, SplineOrder order, const SparseGrid<Dim>& grid)
{
    using Index = typename SparseGrid<Dim>::Index;
    ParticleBuckets<Dim> out;
    // Each particle's base block, by number; then a stable counting sort by it.
    std::vector<int> block_of_particle(static_cast<std::size_t>(particles.size()));
    std::vector<int> count(static_cast<std::size_t>(grid.blocks()) + 1, 0);
    for (int p = 0; p < particles.size(); ++p) {
        const Index base = stencil_base<Dim>(particles.x[static_cast<std::size_t>(p)], grid.dx(), order);
        const int block = grid.block_number(SparseGrid<Dim>::block_of(base));
        if (block < 0)
            throw std::logic_error("bucket_particles: particle " + std::to_string(p) + "'s block is not on the grid");
        block_of_particle[static_cast<std::size_t>(p)] = block;
        ++count[static_cast<std::size_t>(block) + 1];
    }
    for (std::size_t b = 1; b < count.size(); ++b)
        count[b] += count[b - 1];
    out.order.resize(static_cast<std::size_t>(particles.size()));
    std::vector<int> next(count.begin(), count.end() - 1);
    for (int p = 0; p < particles.size(); ++p)
        out.order[static_cast<std::size_t>(next[static_cast<std::size_t>(block_of_particle[static_cast<std::size_t>(p)])]++)] = p;
    for (int block = 0; block < grid.blocks(); ++block) {
        const int first = count[static_cast<std::size_t>(block)], last = count[static_cast<std::size_t>(block) + 1];
        if (first == last)
            continue;
        typename ParticleBuckets<Dim>::Bucket bucket;
        bucket.block = SparseGrid<Dim>::block_of(grid.node(block * SparseGrid<Dim>::kBlockNodes));
        bucket.first = first;
        bucket.last = last;
        int colour = 0;
        for (int a = 0; a < Dim; ++a)
            colour |= (bucket.block[a] & 1) << a;
        for (int corner = 0; corner < ParticleBuckets<Dim>::kCorners; ++corner) {
            Index neighbour = bucket.block;
            for (int a = 0; a < Dim; ++a)
                neighbour[a] += (corner >> a) & 1;
            bucket.neighbours[static_cast<std::size_t>(corner)] = grid.block_number(neighbour);
        }
        out.colours[static_cast<std::size_t>(colour)].push_back(static_cast<int>(out.buckets.size()));
        out.buckets.push_back(bucket);
    }
    return out;
}

template void touch_stencil_blocks<2>(const Particles<2>&, SplineOrder, SparseGrid<2>&);
template void touch_stencil_blocks<3>(const Particles<3>&, SplineOrder, SparseGrid<3>&);
template ParticleBuckets<2> bucket_particles<2>(const Particles<2>&, SplineOrder, const SparseGrid<2>&);
template ParticleBuckets<3> bucket_particles<3>(const Particles<3>&, SplineOrder, const SparseGrid<3>&);

} // namespace sinew
