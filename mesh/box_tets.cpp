#include "sinew/mesh/box_tets.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/grid_extent.hpp"

#include <array>
#include <utility>

namespace sinew {

Mesh box_tets(const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, int nx, int ny, int nz)
{
    check_grid_extent("box_tets", lower, upper, Eigen::Vector3i(nx, ny, nz));
    const Eigen::Vector3i cells(nx, ny, nz);
    std::array<std::vector<double>, 3> axes;
    for (int a = 0; a < 3; ++a)
        for (int i = 0; i <= cells[a]; ++i) {
            const double t = double(i) / cells[a];
            axes[a].push_back((1.0 - t) * lower[a] + t * upper[a]);  // exact at both ends
        }
    return box_tets(axes);
}

Mesh box_tets(const std::array<std::vector<double>, 3>& axes)
{
    for (int a = 0; a < 3; ++a) {
        if (axes[a].size() < 2)
            throw InputError("box_tets: axis " + std::to_string(a) + " has fewer than 2 nodes");
        for (size_t i = 1; i < axes[a].size(); ++i)
            if (!(axes[a][i] > axes[a][i - 1]))
                throw InputError("box_tets: the nodes of axis " + std::to_string(a) + " do not increase");
    }
    const int nx = static_cast<int>(axes[0].size()) - 1, ny = static_cast<int>(axes[1].size()) - 1,
              nz = static_cast<int>(axes[2].size()) - 1;
    const auto node_index = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };

    Mesh mesh;
    mesh.kind = ElementKind::tetrahedron;
    mesh.nodes.resize(3, (nx + 1) * (ny + 1) * (nz + 1));
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i)
                mesh.nodes.col(node_index(i, j, k)) << axes[0][i], axes[1][j], axes[2][k];

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
