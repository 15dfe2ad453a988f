#pragma once
// Closed triangle surfaces for the body tests: a unit cube (outward or
// inward facing) and an L-shaped prism with a reflex edge; a body's φ as
// an NLP for the shared derivative check.
#include "sinew/bodies/collision_body.hpp"
#include "sinew/mesh/box_tets.hpp"
#include "sinew/mesh/mesh.hpp"
#include "sinew/mesh/remove_unused_nodes.hpp"
#include "sinew/problems/nlp.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace sinew::test {

/// The unit cube [0, 1]³ as 12 triangles, outward (or inward) facing.
inline Mesh cube_surface(bool outward = true)
{
    Mesh mesh;
    mesh.kind = ElementKind::triangle_3d;
    mesh.nodes.resize(3, 8);
    for (int i = 0; i < 8; ++i)
        mesh.nodes.col(i) << (i & 1), ((i >> 1) & 1), ((i >> 2) & 1);
    const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                              {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    mesh.elements.resize(3, 12);
    for (int t = 0; t < 12; ++t)
        mesh.elements.col(t) << faces[t][0], (outward ? faces[t][1] : faces[t][2]), (outward ? faces[t][2] : faces[t][1]);
    return mesh;
}

/// The L-shaped prism [0, 1]² × [0, ½] without the quarter x, y > ½: the
/// boundary of 2 × 2 × 1 box cells less one, triangles of the tets' faces
/// that only one tet has, facing out. Its edge x = y = ½ is reflex.
inline Mesh l_shaped_surface()
{
    const Mesh box = box_tets(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 0.5), 2, 2, 1);
    std::map<std::array<int, 3>, std::array<int, 3>> once;  // sorted face → oriented face
    for (int e = 0; e < box.num_elements(); ++e) {
        const Eigen::Vector4i t = box.elements.col(e);
        const Eigen::Vector3d centre = 0.25 * (box.nodes.col(t[0]) + box.nodes.col(t[1]) + box.nodes.col(t[2]) +
                                               box.nodes.col(t[3]));
        if (centre.x() > 0.5 && centre.y() > 0.5)
            continue;
        // Faces of a positively oriented tet, outward: (1,2,3), (0,3,2), (0,1,3), (0,2,1).
        const int faces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
        for (const auto& f : faces) {
            std::array<int, 3> oriented = {t[f[0]], t[f[1]], t[f[2]]}, key = oriented;
            std::sort(key.begin(), key.end());
            if (!once.erase(key))
                once.emplace(key, oriented);
        }
    }
    Mesh mesh;
    mesh.kind = ElementKind::triangle_3d;
    mesh.nodes = box.nodes;
    mesh.elements.resize(3, static_cast<Eigen::Index>(once.size()));
    Eigen::Index column = 0;
    for (const auto& [key, face] : once)
        mesh.elements.col(column++) << face[0], face[1], face[2];
    mesh.element_groups.assign(once.size(), 0);
    mesh.group_names = {kDefaultGroupName};
    remove_unused_nodes(mesh);  // the box's nodes inside the removed cell's corner
    return mesh;
}

/// φ of a body as an unconstrained problem of three variables, so that the
/// shared derivative check compares ∇φ and ∇²φ with differences of φ.
class DistanceProblem final : public Nlp {
public:
    DistanceProblem(const CollisionBody& body, Eigen::Vector3d start) : body_(body), start_(std::move(start))
    {
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col <= row; ++col)
                hessian_.add(row, col);
    }
    std::string name() const override { return "signed-distance"; }
    int num_variables() const override { return 3; }
    Vector starting_point() const override { return start_; }
    double objective(ConstVectorRef x) override { return body_.distance(x).distance; }
    void gradient(ConstVectorRef x, VectorRef g) override { g = body_.distance(x).gradient; }
    const SparsityPattern& hessian_pattern() const override { return hessian_; }

protected:
    void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef, VectorRef values) override
    {
        const Eigen::Matrix3d h = sigma * body_.distance(x).hessian;
        int k = 0;
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col <= row; ++col)
                values[k++] = h(row, col);
    }

private:
    const CollisionBody& body_;
    Vector start_;
    SparsityPattern hessian_;
};

} // namespace sinew::test
