#include "sinew/energies/potentials/assembly_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

/// Blocks no smaller than this many elements on average: smaller ones cost
/// more in scheduling than they bring in parallelism.
constexpr int kMinElementsPerBlock = 32;

/// Greedy first-fit coloring of the blocks in block order: each takes the
/// smallest color no block sharing a node with it has.
std::vector<int> color_blocks(const Eigen::MatrixXi& elements, const std::vector<int>& block_of, int num_blocks,
                              int num_nodes)
{
    // Blocks around each node (sorted, unique).
    std::vector<std::vector<int>> node_blocks(static_cast<std::size_t>(num_nodes));
    for (int e = 0; e < elements.cols(); ++e)
        for (int a = 0; a < elements.rows(); ++a) {
            std::vector<int>& blocks = node_blocks[elements(a, e)];
            if (std::find(blocks.begin(), blocks.end(), block_of[e]) == blocks.end())
                blocks.push_back(block_of[e]);
        }
    std::vector<std::vector<int>> neighbors(static_cast<std::size_t>(num_blocks));
    for (const std::vector<int>& blocks : node_blocks)
        for (int b : blocks)
            for (int c : blocks)
                if (b != c)
                    neighbors[b].push_back(c);
    std::vector<int> color(static_cast<std::size_t>(num_blocks), -1);
    for (int b = 0; b < num_blocks; ++b) {
        std::vector<bool> taken;
        for (int c : neighbors[b])
            if (color[c] >= 0) {
                if (color[c] >= static_cast<int>(taken.size()))
                    taken.resize(static_cast<std::size_t>(color[c]) + 1, false);
                taken[color[c]] = true;
            }
        int first_free = 0;
        while (first_free < static_cast<int>(taken.size()) && taken[first_free])
            ++first_free;
        color[b] = first_free;
    }
    return color;
}

} // namespace

AssemblySchedule schedule_assembly(const Eigen::MatrixXd& nodes, const Eigen::MatrixXi& elements)
{
    AssemblySchedule schedule;
    const int count = static_cast<int>(elements.cols());
    if (count == 0) {
        schedule.color_starts = {0};
        schedule.block_starts = {0};
        return schedule;
    }

    // The longest axis of the bounding box of the elements' nodes.
    Eigen::VectorXd low = nodes.col(elements(0, 0)), high = low;
    for (int e = 0; e < count; ++e)
        for (int a = 0; a < elements.rows(); ++a) {
            low = low.cwiseMin(nodes.col(elements(a, e)));
            high = high.cwiseMax(nodes.col(elements(a, e)));
        }
    int axis = 0;
    const double length = (high - low).maxCoeff(&axis);

    // Element centroids along the axis, and the mean element extent along it.
    std::vector<double> position(static_cast<std::size_t>(count));
    double mean_extent = 0.0;
    for (int e = 0; e < count; ++e) {
        double lo = nodes(axis, elements(0, e)), hi = lo, sum = 0.0;
        for (int a = 0; a < elements.rows(); ++a) {
            const double coordinate = nodes(axis, elements(a, e));
            lo = std::min(lo, coordinate);
            hi = std::max(hi, coordinate);
            sum += coordinate;
        }
        position[e] = sum / static_cast<double>(elements.rows());
        mean_extent += hi - lo;
    }
    mean_extent /= count;

    // Slabs about two elements thick.
    const double slabs = mean_extent > 0.0 ? std::floor(length / (2.0 * mean_extent)) : 1.0;
    const int num_blocks =
        static_cast<int>(std::max(1.0, std::min({slabs, static_cast<double>(count / kMinElementsPerBlock), 4096.0})));
    std::vector<int> block_of(static_cast<std::size_t>(count));
    for (int e = 0; e < count; ++e) {
        // In [0, 1] for any coordinates, also where sums overflowed (NaN → 0).
        const double relative = length > 0.0 ? (position[e] - low[axis]) / length : 0.0;
        const double clamped = relative >= 0.0 ? std::min(relative, 1.0) : 0.0;
        block_of[e] = std::min(num_blocks - 1, static_cast<int>(clamped * num_blocks));
    }

    const std::vector<int> color = color_blocks(elements, block_of, num_blocks, static_cast<int>(nodes.cols()));
    const int num_colors = *std::max_element(color.begin(), color.end()) + 1;

    // Blocks by color (block order within a color), elements by block and in
    // mesh order inside a block (meshes number neighbors close together, which
    // keeps the writes of consecutive elements close in memory).
    std::vector<int> block_order(static_cast<std::size_t>(num_blocks));
    for (int b = 0; b < num_blocks; ++b)
        block_order[b] = b;
    std::stable_sort(block_order.begin(), block_order.end(), [&](int a, int b) { return color[a] < color[b]; });
    std::vector<int> rank_of_block(static_cast<std::size_t>(num_blocks));
    for (int r = 0; r < num_blocks; ++r)
        rank_of_block[block_order[r]] = r;

    schedule.elements.resize(static_cast<std::size_t>(count));
    for (int e = 0; e < count; ++e)
        schedule.elements[e] = e;
    std::sort(schedule.elements.begin(), schedule.elements.end(), [&](int a, int b) {
        const int ra = rank_of_block[block_of[a]], rb = rank_of_block[block_of[b]];
        return ra != rb ? ra < rb : a < b;
    });

    schedule.block_starts.assign(static_cast<std::size_t>(num_blocks) + 1, 0);
    for (int e = 0; e < count; ++e)
        ++schedule.block_starts[rank_of_block[block_of[e]] + 1];
    for (int r = 0; r < num_blocks; ++r)
        schedule.block_starts[r + 1] += schedule.block_starts[r];
    schedule.color_starts.assign(static_cast<std::size_t>(num_colors) + 1, 0);
    for (int b = 0; b < num_blocks; ++b)
        ++schedule.color_starts[color[b] + 1];
    for (int c = 0; c < num_colors; ++c)
        schedule.color_starts[c + 1] += schedule.color_starts[c];
    return schedule;
}

} // namespace sinew
