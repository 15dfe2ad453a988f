#pragma once
// The parameters θ of a muscle-driven facial rig (seed 000 §2).
#include <Eigen/Core>

#include <string>
#include <vector>

namespace sinew {

/// θ = (θ_a, θ_k): one activation per muscle (§2.1), then the cranium's
/// affine map M_c, t_c (§2.2) and the jaw's M_j, t_j (§2.3), 12 parameters
/// each. Packed in that order, each map row by row (entry 3i + j is M_ij)
/// followed by its translation. M_c and M_j need not be orthogonal here: the
/// fitting problem constrains them (or penalizes, in the seed's form).
struct RigParameters {
    static constexpr int kAffineParameters = 12;

    Eigen::VectorXd activations;
    Eigen::Matrix3d cranium_map = Eigen::Matrix3d::Identity();
    Eigen::Vector3d cranium_translation = Eigen::Vector3d::Zero();
    Eigen::Matrix3d jaw_map = Eigen::Matrix3d::Identity();
    Eigen::Vector3d jaw_translation = Eigen::Vector3d::Zero();

    int num_muscles() const { return static_cast<int>(activations.size()); }
    int size() const { return num_muscles() + 2 * kAffineParameters; }
    /// Index of M_c(0,0) and of M_j(0,0) in the packed vector.
    int cranium_offset() const { return num_muscles(); }
    int jaw_offset() const { return num_muscles() + kAffineParameters; }

    Eigen::VectorXd packed() const;
    /// θ of `muscles` activations from a packed vector; InputError for a
    /// size other than muscles + 24 or a non-finite entry.
    static RigParameters unpacked(const Eigen::VectorXd& theta, int muscles);
    /// Activations 0, both maps the identity, no translation: the rest rig.
    static RigParameters neutral(int muscles);
};

/// The name of packed entry `index`: "activation of <muscle>", "M_c(0,1)",
/// "t_j(2)", … (messages and tables).
std::string rig_parameter_name(int index, const std::vector<std::string>& muscle_names);

} // namespace sinew
