// The frame in which an implicit MPM solve moves a node its walls and
// colliders hold: v = offset + B y satisfies every active condition for
// every y, and B spans all the velocities that do.
#include "sinew/mpm/node_velocity_frame.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace sinew;

namespace {

using Frame3 = NodeVelocityFrame<3>;

/// B has orthonormal columns, and offset + B y meets n·v = n·v_b of every row given for random y.
void check_holds(const Frame3& frame, const std::vector<NodeContact<3>>& fixed)
{
    const Eigen::MatrixXd gram = frame.basis.transpose() * frame.basis;
    CHECK((gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).norm() < 1e-14);
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 5; ++trial) {
        Eigen::VectorXd y(frame.basis.cols());
        for (int k = 0; k < y.size(); ++k)
            y[k] = normal(rng);
        const Eigen::Vector3d v = frame.offset + frame.basis * y;
        for (const NodeContact<3>& contact : fixed)
            CHECK(std::abs(contact.normal.dot(v - contact.velocity)) < 1e-14);
    }
}

} // namespace

TEST_CASE("node velocity frame: a free node keeps every velocity")
{
    const Frame3 frame = node_velocity_frame<3>({}, Eigen::Vector3d(1.0, 2.0, 3.0));
    CHECK(frame.basis.cols() == 3);
    CHECK(frame.offset.norm() == 0.0);
}

TEST_CASE("node velocity frame: slip fixes the normal part, against a moving collider too")
{
    const NodeContact<3> floor{GridCondition::slip, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
    const Frame3 on_floor = node_velocity_frame<3>({floor}, Eigen::Vector3d(0.0, 0.0, 1.0));
    CHECK(on_floor.basis.cols() == 2);
    check_holds(on_floor, {floor});
    const NodeContact<3> moving{GridCondition::slip, Eigen::Vector3d(0.5, -1.0, 2.0),
                                Eigen::Vector3d(1.0, 1.0, 0.0).normalized()};
    const Frame3 against = node_velocity_frame<3>({moving}, Eigen::Vector3d::Zero());
    CHECK(against.basis.cols() == 2);
    check_holds(against, {moving});
}

TEST_CASE("node velocity frame: separate holds only a node whose predictor approaches")
{
    const NodeContact<3> floor{GridCondition::separate, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
    CHECK(node_velocity_frame<3>({floor}, Eigen::Vector3d(0.0, 0.0, 1.0)).basis.cols() == 3);
    const Frame3 approaching = node_velocity_frame<3>({floor}, Eigen::Vector3d(0.3, 0.0, -1.0));
    CHECK(approaching.basis.cols() == 2);
    check_holds(approaching, {floor});
}

TEST_CASE("node velocity frame: sticky, a corner of two slip walls, and a collider without a normal")
{
    const NodeContact<3> sticky{GridCondition::sticky, Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d::UnitZ()};
    const Frame3 held = node_velocity_frame<3>({sticky}, Eigen::Vector3d::Zero());
    CHECK(held.basis.cols() == 0);
    CHECK((held.offset - sticky.velocity).norm() < 1e-14);
    const NodeContact<3> floor{GridCondition::slip, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()};
    const NodeContact<3> wall{GridCondition::slip, Eigen::Vector3d::Zero(), -Eigen::Vector3d::UnitX()};
    const Frame3 corner = node_velocity_frame<3>({floor, wall}, Eigen::Vector3d(1.0, 1.0, 1.0));
    REQUIRE(corner.basis.cols() == 1);
    CHECK(std::abs(corner.basis.col(0).dot(Eigen::Vector3d::UnitY())) == Approx(1.0).epsilon(1e-14));
    check_holds(corner, {floor, wall});
    // The same wall twice is one condition, not two.
    CHECK(node_velocity_frame<3>({floor, floor}, Eigen::Vector3d::Zero()).basis.cols() == 2);
    const NodeContact<3> centre{GridCondition::separate, Eigen::Vector3d(0.0, 1.0, 0.0), Eigen::Vector3d::Zero()};
    const Frame3 at_centre = node_velocity_frame<3>({centre}, Eigen::Vector3d::Zero());
    CHECK(at_centre.basis.cols() == 0);
    CHECK((at_centre.offset - centre.velocity).norm() < 1e-14);
}
