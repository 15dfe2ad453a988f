#include "sinew/energies/models/model_catalog.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/codimensional_corotated.hpp"
#include "sinew/energies/models/fixed_corotated.hpp"
#include "sinew/energies/models/mooney_rivlin_muscle.hpp"
#include "sinew/energies/models/plane_fixed_corotated.hpp"
#include "sinew/energies/models/plane_stable_neo_hookean.hpp"
#include "sinew/energies/models/qr_anisotropic.hpp"
#include "sinew/energies/models/stable_neo_hookean.hpp"

namespace sinew {
namespace {

/// Registers Model as the entry's maker for its shape of F.
template <typename Model>
void add_maker(ModelEntry& entry)
{
    constexpr int Rows = Model::Deformation::RowsAtCompileTime, Cols = Model::Deformation::ColsAtCompileTime;
    using Base = ConstitutiveModel<Rows, Cols>;
    auto make = [](const ParameterValues& values) -> std::unique_ptr<Base> { return std::make_unique<Model>(values); };
    if constexpr (Rows == 3 && Cols == 3)
        entry.make_3x3 = make;
    else if constexpr (Rows == 2 && Cols == 2)
        entry.make_2x2 = make;
    else
        entry.make_3x2 = make;
}

/// The catalog entry of a model: the name and parameters of Model, and a
/// maker for Model and for each class of OtherShapes (one per shape of F).
template <typename Model, typename... OtherShapes>
ModelEntry entry_of(const std::string& description)
{
    ModelEntry entry;
    entry.name = Model::kName;
    entry.description = description;
    entry.parameters = Model::parameter_specs();
    add_maker<Model>(entry);
    (add_maker<OtherShapes>(entry), ...);
    return entry;
}

template <int Rows, int Cols>
const std::function<std::unique_ptr<ConstitutiveModel<Rows, Cols>>(const ParameterValues&)>&
maker_for(const ModelEntry& entry)
{
    if constexpr (Rows == 3 && Cols == 3)
        return entry.make_3x3;
    else if constexpr (Rows == 2 && Cols == 2)
        return entry.make_2x2;
    else
        return entry.make_3x2;
}

template <int Rows, int Cols>
const ModelEntry& entry_taking(const std::string& name)
{
    const ModelEntry& entry = find_model(name);
    if (!maker_for<Rows, Cols>(entry)) {
        std::string shapes;
        for (const auto& s : entry.shapes())
            shapes += (shapes.empty() ? "" : " or ") + s;
        throw InputError("model '" + name + "' takes F of shape " + shapes + ", not " + std::to_string(Rows) + "x" +
                         std::to_string(Cols));
    }
    return entry;
}

} // namespace

std::vector<std::string> ModelEntry::shapes() const
{
    std::vector<std::string> result;
    if (make_3x3)
        result.push_back("3x3");
    if (make_2x2)
        result.push_back("2x2");
    if (make_3x2)
        result.push_back("3x2");
    return result;
}

const std::vector<ModelEntry>& model_catalog()
{
    static const std::vector<ModelEntry> catalog = {
        entry_of<MooneyRivlinMuscle>("Mooney-Rivlin solid with active and passive muscle fibers (seed 000 §4-5)"),
        entry_of<CodimensionalCorotated>("corotated membrane for triangles in 3D, F 3x2 (seed 002)"),
        entry_of<QrAnisotropic<3>, QrAnisotropic<2>>(
            "QR-based anisotropic elasticity with damage, 2D or 3D by the size of F (seed 004 §3)"),
        entry_of<StableNeoHookean, PlaneStableNeoHookean>("stable Neo-Hookean (Smith, de Goes, Kim 2018), 3D or plane"),
        entry_of<FixedCorotated, PlaneFixedCorotated>("fixed corotated (Stomakhin et al. 2012), 3D or plane"),
    };
    return catalog;
}

const ModelEntry& find_model(const std::string& name)
{
    std::string valid;
    for (const ModelEntry& entry : model_catalog()) {
        if (entry.name == name)
            return entry;
        valid += (valid.empty() ? "" : ", ") + entry.name;
    }
    throw InputError("unknown model '" + name + "'; valid models: " + valid);
}

template <int Rows, int Cols>
std::unique_ptr<ConstitutiveModel<Rows, Cols>> make_model(const std::string& name, const ParameterText& parameters)
{
    const ModelEntry& entry = entry_taking<Rows, Cols>(name);
    return maker_for<Rows, Cols>(entry)(resolve_parameters(name, entry.parameters, parameters));
}

template <int Rows, int Cols>
std::unique_ptr<ConstitutiveModel<Rows, Cols>> make_model(const std::string& name, const ParameterValues& parameters)
{
    const ModelEntry& entry = entry_taking<Rows, Cols>(name);
    return maker_for<Rows, Cols>(entry)(resolve_parameters(name, entry.parameters, parameters));
}

template std::unique_ptr<Model3d> make_model<3, 3>(const std::string&, const ParameterText&);
template std::unique_ptr<Model2d> make_model<2, 2>(const std::string&, const ParameterText&);
template std::unique_ptr<MembraneModel> make_model<3, 2>(const std::string&, const ParameterText&);
template std::unique_ptr<Model3d> make_model<3, 3>(const std::string&, const ParameterValues&);
template std::unique_ptr<Model2d> make_model<2, 2>(const std::string&, const ParameterValues&);
template std::unique_ptr<MembraneModel> make_model<3, 2>(const std::string&, const ParameterValues&);

} // namespace sinew
