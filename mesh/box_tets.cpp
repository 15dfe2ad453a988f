#include "sinew/mesh/box_tets.hpp"

#include "sinew/mesh/grid_extent.hpp"

#include <array>
#include <utility>

namespace sinew {

Mesh box_tets(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, int nx, int ny, int nz)
{
    check_grid_extent("box_tets", lower, upper, Eigen::Vector3i(nx, ny, nz));
    const auto node_index = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };

    Mesh mesh;
    mesh.kind = ElementKind::tetrahedron;
    mesh.nodes.resize(3, (nx + 1) * (ny + 1) * (nz + 1));
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                const Eigen::Vector3d t(double(i) / nx, double(j) / ny, double(k) / nz);
                // (1 − t)·lower + t·upper is exact at both ends of each axis.
                mesh.nodes.col(node_index(i, j, k)) =
                    (Eigen::Vector3d::Ones() - t).cwiseProduct(lower) + t.cwiseProduct(upper);
            }

    // Kuhn split of the unit cell: for each permutation σ of the axes, the
    // tet walks from corner (0,0,0) to (1,1,1) one axis at a time,
    //     p0 = 0, p1 = e_σ0, p2 = e_σ0 + e_σ1, p3 = (1,1,1),
    // and det[p1 − p0, p2 − p0, p3 − p0] = det[e_σ0, e_σ1, e_σ2] = sign(σ):
    // the odd permutations get their last two nodes swapped.
    const std::array<std::array<int, 3>, 6> permutations{
        {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
    mesh.elements.resize(4, 6 * nx * ny * nz);
    int e = 0;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                for (std::size_t p = 0; p < permutations.size(); ++p) {
                    std::array<int, 3> corner{i, j, k};
                    std::array<int, 4> tet;
                    tet[0] = node_index(corner[0], corner[1], corner[2]);
                    for (int step = 0; step < 3; ++step) {
                        ++corner[permutations[p][step]];
                        tet[step + 1] = node_index(corner[0], corner[1], corner[2]);
                    }
                    if (p >= 3)
                        std::swap(tet[2], tet[3]);
                    for (int n = 0; n < 4; ++n)
                        mesh.elements(n, e) = tet[n];
                    ++e;
                }
    mesh.group_names = {kDefaultGroupName};
    mesh.element_groups.assign(mesh.num_elements(), 0);
    return mesh;
}

} // namespace sinew
