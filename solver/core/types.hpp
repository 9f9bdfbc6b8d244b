// Scalar and small fixed-size vector types used everywhere in the solver (2D only).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>  // determinant() and inverse() of the 2x2 matrices
#include <cstdint>
#include <vector>

namespace mrsph {

using Real = double;
using Vec2 = Eigen::Matrix<Real, 2, 1>;
using Mat2 = Eigen::Matrix<Real, 2, 2>;
using Index = std::int32_t;

// std::vector of fixed-size Eigen types needs no special allocator since C++17
// (Vec2 and Mat2 have alignment requirements that operator new honours).
using Vec2Array = std::vector<Vec2>;
using Mat2Array = std::vector<Mat2>;
using RealArray = std::vector<Real>;

inline constexpr Real kPi = 3.14159265358979323846;
inline constexpr int kDimension = 2;

}  // namespace mrsph
