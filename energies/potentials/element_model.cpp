#include "sinew/energies/potentials/element_model.hpp"

#include "sinew/energies/models/model_catalog.hpp"

namespace sinew {

std::string shape_of(const ElementModel& model)
{
    switch (model.index()) {
    case 0: return "3x3";
    case 1: return "2x2";
    default: return "3x2";
    }
}

std::string shape_of(ElementKind kind)
{
    switch (kind) {
    case ElementKind::tetrahedron: return "3x3";
    case ElementKind::triangle_2d: return "2x2";
    case ElementKind::triangle_3d: return "3x2";
    }
    return "?";
}

std::string name_of(const ElementModel& model)
{
    return std::visit([](const auto& m) { return m ? m->name() : std::string("null"); }, model);
}

namespace {

template <typename Parameters>
ElementModel make_for_kind(ElementKind kind, const std::string& name, const Parameters& parameters)
{
    switch (kind) {
    case ElementKind::tetrahedron: return std::shared_ptr<const Model3d>(make_model<3, 3>(name, parameters));
    case ElementKind::triangle_2d: return std::shared_ptr<const Model2d>(make_model<2, 2>(name, parameters));
    case ElementKind::triangle_3d: return std::shared_ptr<const MembraneModel>(make_model<3, 2>(name, parameters));
    }
    return {};
}

} // namespace

ElementModel make_element_model(ElementKind kind, const std::string& name, const ParameterValues& parameters)
{
    return make_for_kind(kind, name, parameters);
}

ElementModel parse_element_model(ElementKind kind, const std::string& name, const ParameterText& parameters)
{
    return make_for_kind(kind, name, parameters);
}

} // namespace sinew
