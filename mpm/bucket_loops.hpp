#pragma once
// The parallel loops over a step's buckets (particle_buckets.hpp), with
// OpenMP pragmas: internal to mpm/, whose sources are built with OpenMP.
#include "sinew/mpm/particle_buckets.hpp"

#include <vector>

namespace sinew {

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
