#pragma once
// Eigen aliases used throughout sheetform. Nodal arrays are column-per-node (Matrix3Xd), the
// same memory order as an HDF5 [N][3] dataset.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

namespace sf {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;
using Matrix3X = Eigen::Matrix3Xd;
using VectorX = Eigen::VectorXd;
using Quad3 = Eigen::Matrix<double, 3, 4>;  ///< coordinates (or vectors) of a quad's 4 nodes
using Tri3 = Eigen::Matrix<double, 3, 3>;   ///< coordinates of a triangle's 3 nodes (columns)
using QuadConn = Eigen::Matrix<int, 4, Eigen::Dynamic>;  ///< quad connectivity, column per element
using TriConn =
    Eigen::Matrix<int, 3, Eigen::Dynamic>;  ///< triangle connectivity, column per element

}  // namespace sf
