// The model catalog: every model builds at its defaults in every shape it
// takes, is at rest at F = I where it has no fiber prestress, and names the
// parameter or shape it rejects.
#include "sinew/core/input_error.hpp"
#include "sinew/energies/models/model_catalog.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace sinew;

namespace {

template <int Rows, int Cols>
void check_builds_and_evaluates(const std::string& name)
{
    const auto model = make_model<Rows, Cols>(name, ParameterText{});
    REQUIRE(model);
    CHECK(model->name() == name);
    typename ConstitutiveModel<Rows, Cols>::Stress P;
    typename ConstitutiveModel<Rows, Cols>::Stiffness dPdF;
    const double psi = model->evaluate(Eigen::Matrix<double, Rows, Cols>::Identity(), MaterialPoint<Cols>{}, &P,
                                       &dPdF, Projection::none);
    CHECK(std::isfinite(psi));
    CHECK(P.allFinite());
    CHECK(dPdF.allFinite());
}

} // namespace

TEST_CASE("every catalog model builds at its defaults in every shape it takes")
{
    REQUIRE(model_catalog().size() == 5);
    for (const ModelEntry& entry : model_catalog()) {
        CAPTURE(entry.name);
        REQUIRE_FALSE(entry.shapes().empty());
        for (const ParameterSpec& spec : entry.parameters) {
            CAPTURE(spec.name);
            CHECK_FALSE(spec.description.empty());
            if (spec.choices.empty())
                CHECK_FALSE(spec.unit.empty());
        }
        for (const std::string& shape : entry.shapes()) {
            if (shape == "3x3")
                check_builds_and_evaluates<3, 3>(entry.name);
            else if (shape == "2x2")
                check_builds_and_evaluates<2, 2>(entry.name);
            else
                check_builds_and_evaluates<3, 2>(entry.name);
        }
    }
}

TEST_CASE("the catalog names what it rejects")
{
    auto message = [](auto&& make) -> std::string {
        try {
            make();
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    CHECK_THAT(message([] { find_model("neo-hookean"); }), Catch::Contains("valid models"));
    CHECK_THAT(message([] { make_model<3, 2>("stable-neo-hookean", ParameterText{}); }),
               Catch::Contains("3x3"));
    CHECK_THAT(message([] { make_model<3, 3>("codim-corotated", ParameterText{}); }), Catch::Contains("3x2"));
    CHECK_THAT(message([] { make_model<3, 3>("fixed-corotated", ParameterText{{"nu", "0.3"}}); }),
               Catch::Contains("nu"));
    CHECK_THAT(message([] { make_model<3, 3>("fixed-corotated", ParameterText{{"mu", "abc"}}); }),
               Catch::Contains("mu"));
    CHECK_THAT(message([] { make_model<3, 3>("fixed-corotated", ParameterText{{"mu", "nan"}}); }),
               Catch::Contains("mu"));
}
