#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/core/format_number.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <complex>

namespace sinew {
namespace {

/// A prescribed rotation turns by at most this many degrees (100 turns).
constexpr double kMaxTurnDegrees = 36000.0;

/// A load step s moves a set by M(s) = I + s(M − I) (scene.hpp). det M(s) =
/// Π(1 + s μᵢ) over the eigenvalues μᵢ of M − I vanishes for some s ∈ (0, 1]
/// exactly when a real μᵢ ≤ −1, i.e. when M has a real eigenvalue λ ≤ 0: such
/// a map (singular, a reflection, a flattening) collapses the set on the way.
void require_blend_regular(const JsonCursor& where, const Eigen::MatrixXd& M)
{
    const double scale = M.cwiseAbs().maxCoeff();
    const Eigen::VectorXcd eigenvalues = M.eigenvalues();
    for (Eigen::Index i = 0; i < eigenvalues.size(); ++i) {
        const std::complex<double> lambda = eigenvalues[i];
        if (std::abs(lambda.imag()) <= 1e-12 * scale && lambda.real() <= 1e-12 * scale)
            where.fail("the map has the real eigenvalue " + format_number(lambda.real()) +
                       " <= 0: it is singular or reverses orientation, and the load steps I + s(M - I) "
                       "pass through a singular map");
    }
}

PrescribedMotion motion(const JsonCursor& b, int dimension)
{
    PrescribedMotion out;
    out.map = Eigen::MatrixXd::Identity(dimension, dimension);
    out.translation = Eigen::VectorXd::Zero(dimension);
    out.center = Eigen::VectorXd::Zero(dimension);
    if (b.has("rotation") && b.has("map"))
        b.fail("give either rotation or map, not both");
    if (auto r = b.find("rotation")) {
        if (dimension == 3)
            r->expect_object({"axis", "angle_deg", "center"});
        else
            r->expect_object({"angle_deg", "center"});
        out.rotation = true;
        out.angle = r->at("angle_deg").number_in(-kMaxTurnDegrees, kMaxTurnDegrees) * (M_PI / 180.0);
        if (dimension == 3) {
            const Eigen::Vector3d axis = r->at("axis").vector(3);
            if (!(axis.norm() > 0.0))
                r->at("axis").fail("axis must not be zero");
            out.axis = axis.normalized();
        }
        if (auto c = r->find("center"))
            out.center = c->vector(dimension);
    }
    if (auto m = b.find("map")) {
        out.map = m->matrix(dimension, dimension);
        require_blend_regular(*m, out.map);
    }
    if (auto t = b.find("translation"))
        out.translation = t->vector(dimension);
    return out;
}


/// "boundary": Dirichlet sets, each a selection of nodes moved by a rigid
/// rotation or an affine map at load factor 1.
class BoundaryPart final : public ScenePart {
public:
    std::string key() const override { return "boundary"; }
    std::string doc() const override { return "Dirichlet sets: selected nodes held at rest or moved by a rotation or a map"; }
    std::string kind() const override { return "constraints"; }
    int stage() const override { return 40; }
    std::vector<SceneKey> keys() const override
    {
        return {{"[].name", "string", "", "boundary[i]", "the set's name in messages"},
                {"[].select", "selection", "", "", "the nodes of the set", true},
                {"[].rotation", "object", "{axis, angle_deg, center}", "", "x = R(θ)(X − c) + c + t at load factor 1"},
                {"[].map", "matrix", "no real eigenvalue <= 0", "I", "x = M X + t at load factor 1"},
                {"[].translation", "vector", "", "0", "t (m)"}};
    }
    void read(const JsonCursor& list, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        Scene& scene = assembly.scene;
        const int dimension = static_cast<int>(scene.mesh.nodes.rows());
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor b = list[i];
            declared.expect_object(b, "[]");
            PrescribedMotion m = motion(b, dimension);
            DirichletSet set;
            set.name = b.has("name") ? b.at("name").string() : "boundary[" + std::to_string(i) + "]";
            set.nodes = selected_nodes(b.at("select"), scene.mesh, assembly.tolerance);
            set.map = m.map_at(1.0, dimension);
            set.translation = m.translation_at(1.0, dimension);
            assembly.dirichlet_sets.push_back(std::move(set));
            scene.motions.push_back(std::move(m));
        }
    }
};

const SceneRegistration<BoundaryPart> boundary_part;

} // namespace
} // namespace sinew
