#include "sinew/bodies/level_set_body.hpp"

#include "sinew/bodies/surface_body.hpp"
#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/core/threads.hpp"
#include "sinew/mesh/mesh.hpp"

#include <Eigen/LU>
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <mutex>

namespace sinew {

struct LevelSetBody::Grid {
    openvdb::FloatGrid::Ptr grid;
    Eigen::Matrix3d to_index;   ///< A⁻¹ = ∂ξ/∂x, world to index coordinates
    Eigen::Vector3d origin;     ///< x at ξ = 0
};

namespace {

void initialize_openvdb()
{
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

Eigen::Vector3d to_eigen(const openvdb::Vec3d& v) { return {v[0], v[1], v[2]}; }

/// The grid with its affine map read once: ξ = A⁻¹(x − o). InputError
/// (prefixed by `where`) when the transform is not affine.
std::unique_ptr<LevelSetBody::Grid> wrapped(openvdb::FloatGrid::Ptr grid, const std::string& where)
{
    const openvdb::math::Transform& transform = grid->transform();
    if (!transform.isLinear())
        throw InputError(where + ": the grid's transform is not affine (a frustum map); a collision body needs an affine one");
    auto out = std::make_unique<LevelSetBody::Grid>();
    out->grid = std::move(grid);
    out->origin = to_eigen(transform.indexToWorld(openvdb::Vec3d(0.0, 0.0, 0.0)));
    const Eigen::Vector3d xi0 = to_eigen(transform.worldToIndex(openvdb::Vec3d(0.0, 0.0, 0.0)));
    for (int j = 0; j < 3; ++j) {
        openvdb::Vec3d e(0.0, 0.0, 0.0);
        e[j] = 1.0;
        out->to_index.col(j) = to_eigen(transform.worldToIndex(e)) - xi0;  // column j of ∂ξ/∂x
    }
    if (!out->to_index.allFinite() || out->to_index.determinant() == 0.0)
        throw InputError(where + ": the grid's transform is singular");
    return out;
}

/// The grid named `wanted` (any name when empty) among `grids` that is a
/// float level set, or InputError naming the file and the grids it holds.
openvdb::FloatGrid::Ptr level_set_grid(const openvdb::GridPtrVec& grids, const std::string& wanted,
                                       const std::string& path)
{
    std::string seen;
    for (const openvdb::GridBase::Ptr& base : grids) {
        seen += (seen.empty() ? "" : ", ") + ("'" + base->getName() + "' (" + base->valueType() + ", " +
                                              openvdb::GridBase::gridClassToString(base->getGridClass()) + ")");
        if (!wanted.empty() && base->getName() != wanted)
            continue;
        if (base->getGridClass() != openvdb::GRID_LEVEL_SET)
            continue;
        if (auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base))
            return grid;
    }
    const std::string what = wanted.empty() ? "no float level set grid" : "no float level set grid named '" + wanted + "'";
    throw InputError(path + ": " + what + " (grids: " + (seen.empty() ? "none" : seen) + ")");
}

/// φ at index coordinates ξ with ∂φ/∂ξ and ∂²φ/∂ξ².
struct Interpolated {
    double value = 0.0;
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
};

/// The grid's index range: points farther out see the background value.
constexpr double kIndexLimit = 1 << 30;

/// The uniform quadratic B-spline's weights at offset u ∈ [−½, ½) from the
/// nearest voxel centre, for the centres −1, 0, +1, and their first and
/// second derivatives in u:
///   w₋ = ½(½ − u)²,  w₀ = ¾ − u²,  w₊ = ½(½ + u)².
struct AxisWeights {
    double w[3], dw[3], ddw[3];
    explicit AxisWeights(double u)
        : w{0.5 * (0.5 - u) * (0.5 - u), 0.75 - u * u, 0.5 * (0.5 + u) * (0.5 + u)},
          dw{u - 0.5, -2.0 * u, 0.5 + u}, ddw{1.0, -2.0, 1.0}
    {
    }
};

/// φ = Σ_abc φ_abc w_a(u₀) w_b(u₁) w_c(u₂) over the 27 voxels around ξ: C¹
/// (∇φ continuous across voxel faces, like the distance to a smooth
/// surface), and exact for φ linear in ξ.
Interpolated quadratic_b_spline(const openvdb::FloatGrid& grid, const Eigen::Vector3d& xi)
{
    if (!(xi.cwiseAbs().maxCoeff() < kIndexLimit))
        return {grid.background(), Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero()};
    const Eigen::Vector3d nearest = xi.array().round();
    const AxisWeights axis[3] = {AxisWeights(xi[0] - nearest[0]), AxisWeights(xi[1] - nearest[1]),
                                 AxisWeights(xi[2] - nearest[2])};
    const auto accessor = grid.getConstAccessor();
    Interpolated out;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            for (int c = 0; c < 3; ++c) {
                const int at[3] = {a, b, c};
                const openvdb::Coord voxel(static_cast<int>(nearest[0]) + a - 1, static_cast<int>(nearest[1]) + b - 1,
                                           static_cast<int>(nearest[2]) + c - 1);
                const double phi = accessor.getValue(voxel);
                // Each factor of the tensor product, differentiated or not along its axis.
                auto factor = [&](int k, int order) {
                    const AxisWeights& w = axis[k];
                    return order == 0 ? w.w[at[k]] : order == 1 ? w.dw[at[k]] : w.ddw[at[k]];
                };
                out.value += phi * factor(0, 0) * factor(1, 0) * factor(2, 0);
                for (int k = 0; k < 3; ++k) {
                    int order[3] = {0, 0, 0};
                    ++order[k];
                    out.gradient[k] += phi * factor(0, order[0]) * factor(1, order[1]) * factor(2, order[2]);
                    for (int l = 0; l <= k; ++l) {
                        int second[3] = {order[0], order[1], order[2]};
                        ++second[l];
                        out.hessian(k, l) += phi * factor(0, second[0]) * factor(1, second[1]) * factor(2, second[2]);
                    }
                }
            }
    const Eigen::Matrix3d lower = out.hessian;
    out.hessian = lower.selfadjointView<Eigen::Lower>();
    return out;
}

} // namespace

LevelSetBody::LevelSetBody(std::unique_ptr<Grid> grid, std::string name) : grid_(std::move(grid)), name_(std::move(name)) {}
LevelSetBody::~LevelSetBody() = default;
LevelSetBody::LevelSetBody(LevelSetBody&&) noexcept = default;
LevelSetBody& LevelSetBody::operator=(LevelSetBody&&) noexcept = default;

LevelSetBody LevelSetBody::from_vdb(const std::string& path, const std::string& grid)
{
    initialize_openvdb();
    openvdb::GridPtrVecPtr grids;
    try {
        openvdb::io::File file(path);
        file.open();
        grids = file.getGrids();
        file.close();
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot read it as a VDB file (" + e.what() + ")");
    }
    return LevelSetBody(wrapped(level_set_grid(*grids, grid, path), path), path);
}

LevelSetBody LevelSetBody::from_surface(const Mesh& surface, const std::string& name, double voxel_size,
                                        double half_width)
{
    const SurfaceBody checked(surface, name);  // closed, manifold, not self-intersecting
    const std::string where = "body '" + name + "'";
    if (!std::isfinite(voxel_size) || voxel_size <= 0.0)
        throw InputError(where + ": voxel_size " + format_number(voxel_size) + " must be positive and finite");
    if (!std::isfinite(half_width) || half_width < 1.0 || half_width > 64.0)
        throw InputError(where + ": half_width " + format_number(half_width) + " must lie in [1, 64] voxels");
    const double extent = (checked.upper() - checked.lower()).maxCoeff();
    const double finest = extent / kMaxLevelSetVoxelsAcross;
    if (voxel_size < finest)
        throw InputError(where + ": voxel_size " + format_number(voxel_size) + " is finer than " +
                         format_number(finest) + " (the surface's extent " + format_number(extent) + " over at most " +
                         std::to_string(kMaxLevelSetVoxelsAcross) + " voxels)");
    initialize_openvdb();
    std::vector<openvdb::Vec3s> points;
    for (Eigen::Index i = 0; i < surface.nodes.cols(); ++i)
        points.emplace_back(surface.nodes(0, i), surface.nodes(1, i), surface.nodes(2, i));
    std::vector<openvdb::Vec3I> triangles;
    for (Eigen::Index t = 0; t < surface.elements.cols(); ++t)
        triangles.emplace_back(surface.elements(0, t), surface.elements(1, t), surface.elements(2, t));
    const auto transform = openvdb::math::Transform::createLinearTransform(voxel_size);
    openvdb::FloatGrid::Ptr grid;
    tbb::task_arena arena(threads());  // the one thread setting (core/threads.hpp)
    arena.execute([&] {
        grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, triangles,
                                                                   static_cast<float>(half_width));
    });
    grid->setName(name);
    return LevelSetBody(wrapped(grid, where), name);
}

BodyDistance LevelSetBody::distance(const Eigen::Vector3d& x) const
{
    const Eigen::Matrix3d& J = grid_->to_index;  // A⁻¹
    const Interpolated t = quadratic_b_spline(*grid_->grid, J * (x - grid_->origin));
    BodyDistance out;
    out.distance = t.value;
    out.gradient = J.transpose() * t.gradient;         // ∇φ = A⁻ᵀ ∂φ/∂ξ
    out.hessian = J.transpose() * t.hessian * J;       // ∇²φ = A⁻ᵀ ∂²φ/∂ξ² A⁻¹
    return out;
}

double LevelSetBody::voxel_size() const { return grid_->grid->voxelSize()[0]; }

double LevelSetBody::band_width() const { return std::abs(grid_->grid->background()); }

void LevelSetBody::write_vdb(const std::string& path) const
{
    try {
        openvdb::io::File file(path);
        file.write(openvdb::GridPtrVec{grid_->grid});
        file.close();
    } catch (const std::exception& e) {
        throw InputError(path + ": cannot write the level set (" + e.what() + ")");
    }
}

} // namespace sinew
