#include "sinew/mpm/node_velocity_frame.hpp"

#include <Eigen/QR>

namespace sinew {

template <int Dim>
NodeVelocityFrame<Dim> node_velocity_frame(const std::vector<NodeContact<Dim>>& contacts,
                                           const Eigen::Matrix<double, Dim, 1>& predictor)
{
    using Vector = Eigen::Matrix<double, Dim, 1>;
    NodeVelocityFrame<Dim> frame;
    if (contacts.empty())
        return frame;
    std::vector<Vector> rows;  // N's rows, with d = n · v_b
    std::vector<double> values;
    for (const NodeContact<Dim>& contact : contacts) {
        const Vector& n = contact.normal;
        const bool held = contact.condition == GridCondition::sticky || !(n.squaredNorm() > 0.0);
        const bool approaching = (predictor - contact.velocity).dot(n) < 0.0;
        if (held) {
            for (int a = 0; a < Dim; ++a) {
                rows.push_back(Vector::Unit(a));
                values.push_back(contact.velocity[a]);
            }
        } else if (contact.condition == GridCondition::slip || approaching) {
            rows.push_back(n);
            values.push_back(n.dot(contact.velocity));
        }
    }
    if (rows.empty())
        return frame;
    // Dynamic sizes throughout: one QR type for both solves and both dimensions (compile time).
    Eigen::MatrixXd N_transpose(Dim, static_cast<Eigen::Index>(rows.size()));
    Eigen::VectorXd d(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t k = 0; k < rows.size(); ++k) {
        N_transpose.col(static_cast<Eigen::Index>(k)) = rows[k];
        d[static_cast<Eigen::Index>(k)] = values[k];
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(N_transpose);
    const Eigen::Index rank = qr.rank();
    const Eigen::MatrixXd Q = qr.householderQ();
    frame.basis = Q.rightCols(Dim - rank);  // null space of N
    // Least-norm v with N v = d: v = Q₁ z, z minimizing ‖N Q₁ z − d‖ over the range Q₁ of Nᵀ.
    const Eigen::MatrixXd range = Q.leftCols(rank);
    const Eigen::MatrixXd reduced = N_transpose.transpose() * range;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> reduced_qr(reduced);
    frame.offset = range * reduced_qr.solve(d);
    return frame;
}

template NodeVelocityFrame<2> node_velocity_frame<2>(const std::vector<NodeContact<2>>&, const Eigen::Vector2d&);
template NodeVelocityFrame<3> node_velocity_frame<3>(const std::vector<NodeContact<3>>&, const Eigen::Vector3d&);

} // namespace sinew
