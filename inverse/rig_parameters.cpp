#include "sinew/inverse/rig_parameters.hpp"

#include "sinew/core/input_error.hpp"

#include <string>

namespace sinew {
namespace {

void pack_affine(const Eigen::Matrix3d& map, const Eigen::Vector3d& translation, double* out)
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            out[3 * i + j] = map(i, j);
    for (int i = 0; i < 3; ++i)
        out[9 + i] = translation[i];
}

void unpack_affine(const double* in, Eigen::Matrix3d& map, Eigen::Vector3d& translation)
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            map(i, j) = in[3 * i + j];
    for (int i = 0; i < 3; ++i)
        translation[i] = in[9 + i];
}

} // namespace

Eigen::VectorXd RigParameters::packed() const
{
    Eigen::VectorXd theta(size());
    theta.head(num_muscles()) = activations;
    pack_affine(cranium_map, cranium_translation, theta.data() + cranium_offset());
    pack_affine(jaw_map, jaw_translation, theta.data() + jaw_offset());
    return theta;
}

RigParameters RigParameters::unpacked(const Eigen::VectorXd& theta, int muscles)
{
    if (muscles < 0 || theta.size() != muscles + 2 * kAffineParameters)
        throw InputError("rig parameters: " + std::to_string(theta.size()) + " values given, expected " +
                         std::to_string(muscles) + " activations + 24 affine parameters");
    if (!theta.allFinite())
        throw InputError("rig parameters: a value is not finite");
    RigParameters parameters;
    parameters.activations = theta.head(muscles);
    unpack_affine(theta.data() + parameters.cranium_offset(), parameters.cranium_map, parameters.cranium_translation);
    unpack_affine(theta.data() + parameters.jaw_offset(), parameters.jaw_map, parameters.jaw_translation);
    return parameters;
}

RigParameters RigParameters::neutral(int muscles)
{
    RigParameters parameters;
    parameters.activations = Eigen::VectorXd::Zero(muscles);
    return parameters;
}

std::string rig_parameter_name(int index, const std::vector<std::string>& muscle_names)
{
    const int muscles = static_cast<int>(muscle_names.size());
    if (index < muscles)
        return "activation of " + muscle_names[index];
    const int affine = index - muscles;
    const std::string bone = affine < RigParameters::kAffineParameters ? "c" : "j";
    const int entry = affine % RigParameters::kAffineParameters;
    if (entry < 9)
        return "M_" + bone + "(" + std::to_string(entry / 3) + "," + std::to_string(entry % 3) + ")";
    return "t_" + bone + "(" + std::to_string(entry - 9) + ")";
}

} // namespace sinew
