#include "sinew/energies/models/model_catalog.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/codimensional_corotated.hpp"
#include "sinew/energies/models/fixed_corotated.hpp"
#include "sinew/energies/models/mooney_rivlin_muscle.hpp"
#include "sinew/energies/models/qr_anisotropic.hpp"
#include "sinew/energies/models/stable_neo_hookean.hpp"

namespace sinew {
namespace {

template <typename Model, typename Base>
std::function<std::unique_ptr<Base>(const ParameterValues&)> maker()
{
    return [](const ParameterValues& values) -> std::unique_ptr<Base> { return std::make_unique<Model>(values); };
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
    static const std::vector<ModelEntry> catalog = [] {
        std::vector<ModelEntry> models;
        {
            ModelEntry e;
            e.name = MooneyRivlinMuscle::kName;
            e.description = "Mooney-Rivlin solid with active and passive muscle fibers (seed 000 §4-5)";
            e.parameters = MooneyRivlinMuscle::parameter_specs();
            e.make_3x3 = maker<MooneyRivlinMuscle, Model3d>();
            models.push_back(std::move(e));
        }
        {
            ModelEntry e;
            e.name = CodimensionalCorotated::kName;
            e.description = "corotated membrane for triangles in 3D, F 3x2 (seed 002)";
            e.parameters = CodimensionalCorotated::parameter_specs();
            e.make_3x2 = maker<CodimensionalCorotated, MembraneModel>();
            models.push_back(std::move(e));
        }
        {
            ModelEntry e;
            e.name = QrAnisotropic<3>::kName;
            e.description = "QR-based anisotropic elasticity with damage, 2D or 3D by the size of F (seed 004 §3)";
            e.parameters = QrAnisotropic<3>::parameter_specs();
            e.make_3x3 = maker<QrAnisotropic<3>, Model3d>();
            e.make_2x2 = maker<QrAnisotropic<2>, Model2d>();
            models.push_back(std::move(e));
        }
        {
            ModelEntry e;
            e.name = StableNeoHookean::kName;
            e.description = "stable Neo-Hookean (Smith, de Goes, Kim 2018)";
            e.parameters = StableNeoHookean::parameter_specs();
            e.make_3x3 = maker<StableNeoHookean, Model3d>();
            models.push_back(std::move(e));
        }
        {
            ModelEntry e;
            e.name = FixedCorotated::kName;
            e.description = "fixed corotated (Stomakhin et al. 2012)";
            e.parameters = FixedCorotated::parameter_specs();
            e.make_3x3 = maker<FixedCorotated, Model3d>();
            models.push_back(std::move(e));
        }
        return models;
    }();
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
