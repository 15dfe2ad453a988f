#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/assembly_schedule.hpp"
#include "sinew/energies/potentials/hessian_pattern.hpp"

#include "potentials/test_meshes.hpp"

#include <catch2/catch.hpp>

#include <set>
#include <utility>

using namespace sinew;
using namespace sinew::test;

TEST_CASE("Hessian pattern: lower triangle, compressed-column order, exactly the coupled blocks",
          "[potentials][pattern]")
{
    const Mesh mesh = box_of_tets(2, 2, 1, 1.0);
    const int d = 3;
    Stencils single(1, 1);
    single(0, 0) = 4;  // a node-wise stencil on a node the elements also hold
    const HessianPattern pattern(d, mesh.num_nodes(), {&mesh.elements, &single});

    // The expected entries: every node's diagonal block and every pair of
    // nodes sharing an element.
    std::set<std::pair<int, int>> node_pairs;
    for (int i = 0; i < mesh.num_nodes(); ++i)
        node_pairs.insert({i, i});
    for (int e = 0; e < mesh.num_elements(); ++e)
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b)
                node_pairs.insert({std::max(mesh.elements(a, e), mesh.elements(b, e)),
                                   std::min(mesh.elements(a, e), mesh.elements(b, e))});
    std::set<std::pair<int, int>> expected;
    for (const auto& [i, j] : node_pairs)
        for (int n = 0; n < d; ++n)
            for (int m = 0; m < d; ++m)
                if (i * d + n >= j * d + m)
                    expected.insert({i * d + n, j * d + m});

    REQUIRE(pattern.nonzeros() == static_cast<int>(expected.size()));
    for (int k = 0; k < pattern.nonzeros(); ++k) {
        CHECK(pattern.rows()[k] >= pattern.cols()[k]);
        CHECK(expected.count({pattern.rows()[k], pattern.cols()[k]}) == 1);
        CHECK(pattern.find(pattern.rows()[k], pattern.cols()[k]) == k);
        if (k > 0) {
            const bool ordered = pattern.cols()[k] > pattern.cols()[k - 1] ||
                                 (pattern.cols()[k] == pattern.cols()[k - 1] && pattern.rows()[k] > pattern.rows()[k - 1]);
            CHECK(ordered);
        }
    }
    // Two nodes of no common element are not coupled.
    CHECK(pattern.find(3 * grid_node(2, 2, 1, 2, 2), 3 * grid_node(0, 0, 0, 2, 2)) == -1);
    CHECK(pattern.find(0, 1) == -1);  // above the diagonal
}

TEST_CASE("Hessian pattern: slot tables point at the entry of each local (p, q)", "[potentials][pattern]")
{
    const Mesh mesh = rectangle_of_triangles(3, 2, 1.0);
    const int d = 2;
    const HessianPattern pattern(d, mesh.num_nodes(), {&mesh.elements});
    const StencilSlots slots = pattern.slots(mesh.elements);
    REQUIRE(slots.rows() == 21);
    REQUIRE(slots.cols() == mesh.num_elements());
    for (int e = 0; e < mesh.num_elements(); ++e) {
        int k = 0;
        for (int q = 0; q < 6; ++q)
            for (int p = q; p < 6; ++p) {
                const int row = mesh.elements(p / d, e) * d + p % d;
                const int col = mesh.elements(q / d, e) * d + q % d;
                CHECK(slots(k++, e) == pattern.find(std::max(row, col), std::min(row, col)));
            }
    }
}

TEST_CASE("Hessian pattern: bad stencils are refused", "[potentials][pattern][input]")
{
    Stencils repeated(2, 1);
    repeated << 1, 1;
    CHECK_THROWS_AS(HessianPattern(3, 4, {&repeated}), InputError);
    Stencils outside(2, 1);
    outside << 1, 4;
    CHECK_THROWS_WITH(HessianPattern(3, 4, {&outside}), Catch::Contains("node 4"));
}

TEST_CASE("assembly schedule: blocks of one color share no node, every element once, few colors",
          "[potentials][pattern]")
{
    const Mesh mesh = box_of_tets(12, 3, 3, 1.0);
    const AssemblySchedule schedule = schedule_assembly(mesh.nodes, mesh.elements);
    CHECK(schedule.num_blocks() == 6);  // slabs two cells thick along the long axis
    CHECK(schedule.num_colors() == 2);
    std::vector<int> seen(mesh.num_elements(), 0);
    for (int c = 0; c < schedule.num_colors(); ++c) {
        std::set<int> color_nodes;
        for (int b = schedule.color_starts[c]; b < schedule.color_starts[c + 1]; ++b) {
            std::set<int> block_nodes;
            for (int k = schedule.block_starts[b]; k < schedule.block_starts[b + 1]; ++k) {
                const int e = schedule.elements[k];
                ++seen[e];
                for (int a = 0; a < 4; ++a)
                    block_nodes.insert(mesh.elements(a, e));
            }
            for (int node : block_nodes)
                CHECK(color_nodes.insert(node).second);
        }
    }
    for (int count : seen)
        CHECK(count == 1);
    // A tiny mesh is one block.
    const Mesh small = box_of_tets(1, 1, 1, 1.0);
    CHECK(schedule_assembly(small.nodes, small.elements).num_blocks() == 1);
}
