/**
 * @file rve_tensor.h
 * Small fixed-size 2D vectors and tensors used by the RVE fix.
 *
 * Tensors are stored row-major: {A11, A12, A21, A22}. The dyadic product
 * a (x) b has components (a (x) b)_ij = a_i b_j. No Eigen here: the fix is
 * compiled into the LIGGGHTS plugin and must stay dependency-free.
 */
#pragma once

#include <array>
#include <cmath>

namespace fe2dem
{
using Vec2 = std::array<double, 2>;
using Mat2 = std::array<double, 4>;

inline Mat2 identity2() { return {{1.0, 0.0, 0.0, 1.0}}; }
inline Vec2 operator+(const Vec2& a, const Vec2& b) { return {{a[0] + b[0], a[1] + b[1]}}; }
inline Vec2 operator-(const Vec2& a, const Vec2& b) { return {{a[0] - b[0], a[1] - b[1]}}; }
inline Vec2 operator*(double s, const Vec2& a) { return {{s * a[0], s * a[1]}}; }
inline double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }
inline double norm(const Vec2& a) { return std::sqrt(dot(a, a)); }
/// a x e3 for an in-plane vector a: rotates a by -90 degrees.
inline Vec2 cross_e3(const Vec2& a) { return {{a[1], -a[0]}}; }

inline Vec2 apply(const Mat2& A, const Vec2& x)
{
  return {{A[0] * x[0] + A[1] * x[1], A[2] * x[0] + A[3] * x[1]}};
}
inline Mat2 outer(const Vec2& a, const Vec2& b)
{
  return {{a[0] * b[0], a[0] * b[1], a[1] * b[0], a[1] * b[1]}};
}
inline Mat2 operator+(const Mat2& A, const Mat2& B)
{
  return {{A[0] + B[0], A[1] + B[1], A[2] + B[2], A[3] + B[3]}};
}
inline Mat2 operator-(const Mat2& A, const Mat2& B)
{
  return {{A[0] - B[0], A[1] - B[1], A[2] - B[2], A[3] - B[3]}};
}
inline Mat2 operator*(double s, const Mat2& A) { return {{s * A[0], s * A[1], s * A[2], s * A[3]}}; }
inline Mat2 matmul(const Mat2& A, const Mat2& B)
{
  return {{A[0] * B[0] + A[1] * B[2], A[0] * B[1] + A[1] * B[3], A[2] * B[0] + A[3] * B[2],
          A[2] * B[1] + A[3] * B[3]}};
}
inline Mat2 transpose(const Mat2& A) { return {{A[0], A[2], A[1], A[3]}}; }
inline double det(const Mat2& A) { return A[0] * A[3] - A[1] * A[2]; }
inline Mat2 inverse(const Mat2& A)
{
  const double d = det(A);
  return {{A[3] / d, -A[1] / d, -A[2] / d, A[0] / d}};
}
inline double frobenius(const Mat2& A)
{
  return std::sqrt(A[0] * A[0] + A[1] * A[1] + A[2] * A[2] + A[3] * A[3]);
}
inline double contract(const Mat2& A, const Mat2& B)
{
  return A[0] * B[0] + A[1] * B[1] + A[2] * B[2] + A[3] * B[3];
}
/// Eigenvalues of the symmetric part, largest first.
inline Vec2 sym_eigenvalues(const Mat2& A)
{
  const double a = A[0], d = A[3], b = 0.5 * (A[1] + A[2]);
  const double m = 0.5 * (a + d), r = std::sqrt(0.25 * (a - d) * (a - d) + b * b);
  return {{m + r, m - r}};
}
} // namespace fe2dem
