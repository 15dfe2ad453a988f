#pragma once
#include <Eigen/Core>

#include <vector>

namespace sinew {

/// The order in which an element loop adds local gradients and Hessians into
/// global arrays, in parallel and deterministically.
///
/// Elements are cut into blocks: slabs across the mesh's longest axis, each
/// about two elements thick, elements sorted along the axis inside. Blocks are
/// colored so that no two blocks of one color share a node (for slabs:
/// alternate colors, 2 or 3 in all). Colors run one after another; within a
/// color, blocks run in parallel, each on one thread, its elements in order.
/// Every global entry then receives the same contributions in the same order
/// — at most one block per color touches it — whatever the number of threads,
/// so the sums are bitwise identical; and there are only as many barriers as
/// colors.
struct AssemblySchedule {
    /// Blocks of color c are color_starts[c] … color_starts[c+1] − 1.
    std::vector<int> color_starts;
    /// Elements of block b are elements[block_starts[b] … block_starts[b+1]).
    std::vector<int> block_starts;
    std::vector<int> elements;

    int num_colors() const { return static_cast<int>(color_starts.size()) - 1; }
    int num_blocks() const { return static_cast<int>(block_starts.size()) - 1; }
};

/// The schedule of a mesh: `nodes` the rest positions (one column per node),
/// `elements` node indices (one column per element, all in range). Depends on
/// the mesh only, never on the thread count.
AssemblySchedule schedule_assembly(const Eigen::MatrixXd& nodes, const Eigen::MatrixXi& elements);

} // namespace sinew
