// ConstitutiveModel::evaluate_batch (what the elastic potential's assembly
// calls) gives every element exactly what evaluate gives it alone, for every
// model of the catalog, every output combination and both projections; and
// the batched fast SVD gives every matrix exactly its own SVD, whatever
// shares its SIMD register (the rare cases included).
#include "sinew/energies/models/fast_rotation_variant_svd.hpp"
#include "sinew/energies/models/model_catalog.hpp"

#include "energies/deformation_regimes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace sinew;
using sinew::test::all_regimes;
using sinew::test::random_deformation;
using sinew::test::random_rotation;
using sinew::test::random_unit_vector;

namespace {

/// Equal entry by entry, bit for bit (NaN equal to NaN).
template <typename Matrix>
bool identical(const Matrix& a, const Matrix& b)
{
    for (int i = 0; i < a.size(); ++i) {
        const double x = a.data()[i], y = b.data()[i];
        if (!(x == y || (std::isnan(x) && std::isnan(y))))
            return false;
    }
    return true;
}

/// Deformation gradients of every regime, and the rare cases of the SVD
/// between them: zero, a rotation (FᵀF = I to rounding), rank one, and
/// scales far outside [1e-50, 1e50].
std::vector<Eigen::Matrix3d> mixed_deformations(std::mt19937& rng)
{
    std::vector<Eigen::Matrix3d> F;
    for (int round = 0; round < 8; ++round)
        for (const auto regime : all_regimes())
            F.push_back(random_deformation<3, 3>(regime, rng));
    const Eigen::Vector3d u = random_unit_vector<3>(rng), v = random_unit_vector<3>(rng);
    const std::vector<Eigen::Matrix3d> rare = {Eigen::Matrix3d::Zero(), random_rotation<3>(rng),
                                               2.0 * u * v.transpose(), 1e60 * random_rotation<3>(rng),
                                               1e-60 * random_deformation<3, 3>(all_regimes()[1], rng)};
    for (size_t k = 0; k < rare.size(); ++k)
        F.insert(F.begin() + static_cast<long>(7 * k + 3), rare[k]);
    return F;
}

template <int Rows, int Cols>
void check_batch_equals_single(const std::string& name, std::mt19937& rng)
{
    using Model = ConstitutiveModel<Rows, Cols>;
    const auto model = make_model<Rows, Cols>(name, ParameterText{});
    std::vector<typename Model::Deformation> F;
    if constexpr (Rows == 3 && Cols == 3) {
        F = mixed_deformations(rng);
    } else {
        for (int round = 0; round < 8; ++round)
            for (const auto regime : all_regimes())
                F.push_back(random_deformation<Rows, Cols>(regime, rng));
    }
    const int count = static_cast<int>(F.size());  // not a multiple of any lane count
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<typename Model::Point> points(F.size());
    for (auto& point : points) {
        point.fiber = random_unit_vector<Cols>(rng);
        point.activation = unit(rng);
        point.damage = unit(rng);
    }
    for (const Projection projection : {Projection::none, Projection::clamp})
        for (const bool stress : {false, true})
            for (const bool stiffness : {false, true}) {
                CAPTURE(name, Rows, Cols, projection == Projection::clamp, stress, stiffness);
                std::vector<double> psi(F.size());
                std::vector<typename Model::Stress> P(F.size());
                std::vector<typename Model::Stiffness> dPdF(F.size());
                model->evaluate_batch(count, F.data(), points.data(), psi.data(), stress ? P.data() : nullptr,
                                      stiffness ? dPdF.data() : nullptr, projection);
                for (int k = 0; k < count; ++k) {
                    CAPTURE(k);
                    typename Model::Stress P_alone;
                    typename Model::Stiffness dPdF_alone;
                    const double psi_alone = model->evaluate(F[k], points[k], stress ? &P_alone : nullptr,
                                                             stiffness ? &dPdF_alone : nullptr, projection);
                    CHECK((psi[k] == psi_alone || (std::isnan(psi[k]) && std::isnan(psi_alone))));
                    if (stress)
                        CHECK(identical(P[k], P_alone));
                    if (stiffness)
                        CHECK(identical(dPdF[k], dPdF_alone));
                }
            }
}

} // namespace

TEST_CASE("fast SVD in batches: each matrix gets exactly its own SVD", "[energies][fast-svd]")
{
    std::mt19937 rng(41);
    const std::vector<Eigen::Matrix3d> F = mixed_deformations(rng);
    for (int count : {1, 2, 3, 5, static_cast<int>(F.size())}) {
        CAPTURE(count);
        std::vector<RotationVariantSvd<3>> batch(F.size());
        fast_rotation_variant_svd(F.data(), count, batch.data());
        for (int k = 0; k < count; ++k) {
            CAPTURE(k);
            const RotationVariantSvd<3> alone = fast_rotation_variant_svd(F[k]);
            CHECK(identical(batch[k].U, alone.U));
            CHECK(identical(batch[k].V, alone.V));
            CHECK(identical(batch[k].sigma, alone.sigma));
            // And a true SVD (the properties are tested in depth in test_fast_svd.cpp).
            const double scale = std::max(F[k].cwiseAbs().maxCoeff(), 1e-300);
            CHECK((batch[k].U * batch[k].sigma.asDiagonal() * batch[k].V.transpose() - F[k]).cwiseAbs().maxCoeff() <=
                  1e-14 * scale);
        }
    }
}

TEST_CASE("evaluate_batch equals evaluate for every model, output and projection", "[energies]")
{
    std::mt19937 rng(43);
    for (const ModelEntry& entry : model_catalog())
        for (const std::string& shape : entry.shapes()) {
            if (shape == "3x3")
                check_batch_equals_single<3, 3>(entry.name, rng);
            else if (shape == "2x2")
                check_batch_equals_single<2, 2>(entry.name, rng);
            else
                check_batch_equals_single<3, 2>(entry.name, rng);
        }
}
