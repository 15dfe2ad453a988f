// The sparse block grid of MPM (issue 33): slots round-trip to nodes,
// blocks exist only where touched, negative indices, and the index bound.
#include "sinew/mpm/sparse_grid.hpp"

#include <catch2/catch.hpp>

#include <set>

using namespace sinew;

TEST_CASE("sparse grid: a touched node keeps its slot, and memory follows the touched blocks")
{
    SparseGrid<3> grid(0.1);
    CHECK(grid.blocks() == 0);
    std::set<int> slots;
    for (int i = -6; i <= 5; ++i)
        for (int j = -2; j <= 1; ++j) {
            const Eigen::Vector3i node(i, j, 100);
            const int slot = grid.touch(node);
            CHECK(grid.touch(node) == slot);
            CHECK(grid.find(node) == slot);
            CHECK(grid.node(slot) == node);
            CHECK(grid.position(slot).isApprox(node.cast<double>() * 0.1));
            slots.insert(slot);
        }
    CHECK(slots.size() == 48);
    // i in [−6, 5] spans blocks −2..1, j in [−2, 1] blocks −1..0, k = 100 one block.
    CHECK(grid.blocks() == 8);
    CHECK(grid.slots() == 8 * 64);
    CHECK(grid.mass.size() == 8 * 64);
    CHECK(grid.find(Eigen::Vector3i(0, 0, 0)) == -1);
    // A node far away makes one more block, not a bounding box of them.
    grid.touch(Eigen::Vector3i(5000, -7000, 9000));
    CHECK(grid.blocks() == 9);
    grid.clear();
    CHECK(grid.blocks() == 0);
    CHECK(grid.find(Eigen::Vector3i(0, 0, 100)) == -1);
}

TEST_CASE("sparse grid: node indices are held below 2^20 in each axis")
{
    const int bound = SparseGrid<2>::kMaxIndex;
    CHECK(SparseGrid<2>::holds(Eigen::Vector2i(bound - 1, -(bound - 1))));
    CHECK_FALSE(SparseGrid<2>::holds(Eigen::Vector2i(bound, 0)));
    CHECK_FALSE(SparseGrid<3>::holds(Eigen::Vector3i(0, 0, -bound)));
    SparseGrid<2> grid(1.0);
    const Eigen::Vector2i corner(bound - 1, -(bound - 1));
    const int slot = grid.touch(corner);
    CHECK(grid.node(slot) == corner);
    CHECK(grid.find(Eigen::Vector2i(bound, 0)) == -1);
}
