#pragma once
#include "sinew/bodies/collision_body.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>

namespace sinew {

struct Mesh;

/// The most voxels a level set body may span along any axis of its
/// surface's bounds: a voxel size that asks for more is an input error.
constexpr int kMaxLevelSetVoxelsAcross = 2000;

/// A rigid collision body given as a narrow-band signed distance field on a
/// sparse OpenVDB grid (the field's format for colliders): read from a
/// `.vdb` file or made from a closed triangle surface by OpenVDB's
/// meshToLevelSet — never a hand-written voxelizer.
///
/// φ between voxel centres is the uniform quadratic B-spline of the voxel
/// values in the grid's index coordinates ξ = A⁻¹(x − o) (its affine
/// transform): with u = ξ − round(ξ) ∈ [−½, ½)³,
///   φ = Σ_abc φ_abc w_a(u₀) w_b(u₁) w_c(u₂),  w = ½(½ − u)², ¾ − u², ½(½ + u)²
/// over the 27 nearest voxels. It is C¹, as the distance to a smooth surface
/// is: ∇φ = A⁻ᵀ ∂φ/∂ξ is continuous across voxel faces (a gap row's Jacobian
/// has no jumps), ∇²φ = A⁻ᵀ (∂²φ/∂ξ²) A⁻¹ jumps there. It reproduces a φ
/// linear in ξ exactly. Beyond the narrow band the grid holds ±(band width):
/// φ is clamped there and ∇φ = 0, so the band must be wider than the
/// deepest penetration a solve can reach (docs/contact.md).
class LevelSetBody final : public CollisionBody {
public:
    /// The first float level-set grid of the `.vdb` file at `path` (or the
    /// grid named `grid`). InputError naming the file: unreadable, not a VDB
    /// file, no float grid of class level set (or no grid of that name), a
    /// transform that is not affine.
    static LevelSetBody from_vdb(const std::string& path, const std::string& grid = "");

    /// The level set of the closed triangle_3d surface `surface` (checked as
    /// SurfaceBody checks it), voxels of edge `voxel_size`, a band of
    /// `half_width` voxels on each side. Runs on threads() cores. InputError
    /// naming `name`: a surface SurfaceBody refuses, a voxel size that is not
    /// positive and finite or spans more than kMaxLevelSetVoxelsAcross
    /// voxels, a half width outside [1, 64].
    static LevelSetBody from_surface(const Mesh& surface, const std::string& name, double voxel_size,
                                     double half_width);

    ~LevelSetBody() override;
    LevelSetBody(LevelSetBody&&) noexcept;
    LevelSetBody& operator=(LevelSetBody&&) noexcept;

    std::string name() const override { return name_; }
    std::string kind() const override { return "level-set"; }
    int dimension() const override { return 3; }
    /// φ, ∇φ and ∇²φ at x (body frame), as above.
    BodyDistance distance(const Eigen::Vector3d& x) const override;

    /// The edge of a voxel along the grid's first index axis, m.
    double voxel_size() const;
    /// |φ| beyond the narrow band (the grid's background value), m.
    double band_width() const;

    /// Writes the grid (named after the body) to a `.vdb` file. InputError
    /// when the file cannot be written.
    void write_vdb(const std::string& path) const;

    struct Grid;  ///< the OpenVDB grid and its transform, opaque outside level_set_body.cpp

private:
    LevelSetBody(std::unique_ptr<Grid> grid, std::string name);
    std::unique_ptr<Grid> grid_;
    std::string name_;
};

} // namespace sinew
