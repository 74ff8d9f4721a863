/**
 * @file rve_tensor.h
 * Small fixed-size vectors and tensors of the RVE fix, in 2D and 3D.
 *
 * Tensors are stored row-major: 2D {A11, A12, A21, A22}, 3D {A11, A12, A13,
 * A21, ..., A33}. The dyadic product a (x) b has components
 * (a (x) b)_ij = a_i b_j. No Eigen here: the fix is compiled into the
 * LIGGGHTS plugin and must stay dependency-free.
 *
 * Every sum starts from its first term and runs in index order, so the 2D
 * results are the same bits as the hand-written 2D formulas they replaced.
 */
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace fe2dem
{
template <int dim>
using Vec = std::array<double, dim>;
template <int dim>
using Mat = std::array<double, dim * dim>;
/// Rotation of a particle: the angle about e3 in 2D, a rotation vector in 3D.
template <int dim>
using Spin = std::array<double, dim == 2 ? 1 : 3>;
/// T in a non-deduced context: templates on dim deduce it from another
/// argument (an int parameter cannot be deduced from std::array's size_t).
template <class T>
struct NonDeduced
{
  using type = T;
};
template <class T>
using Same = typename NonDeduced<T>::type;

using Vec2 = Vec<2>;
using Mat2 = Mat<2>;
using Vec3 = Vec<3>;
using Mat3 = Mat<3>;

template <int dim>
Mat<dim> identity()
{
  Mat<dim> I{};
  for (int i = 0; i < dim; ++i)
    I[i * dim + i] = 1.0;
  return I;
}
inline Mat2 identity2() { return identity<2>(); }

// Element-wise operations on vectors, spins and tensors alike.
template <std::size_t n>
std::array<double, n> operator+(const std::array<double, n>& a, const std::array<double, n>& b)
{
  std::array<double, n> c;
  for (std::size_t k = 0; k < n; ++k)
    c[k] = a[k] + b[k];
  return c;
}
template <std::size_t n>
std::array<double, n> operator-(const std::array<double, n>& a, const std::array<double, n>& b)
{
  std::array<double, n> c;
  for (std::size_t k = 0; k < n; ++k)
    c[k] = a[k] - b[k];
  return c;
}
template <std::size_t n>
std::array<double, n> operator*(double s, const std::array<double, n>& a)
{
  std::array<double, n> c;
  for (std::size_t k = 0; k < n; ++k)
    c[k] = s * a[k];
  return c;
}
/// Sum of a_k b_k (for tensors: A : B).
template <std::size_t n>
double dot(const std::array<double, n>& a, const std::array<double, n>& b)
{
  double s = a[0] * b[0];
  for (std::size_t k = 1; k < n; ++k)
    s += a[k] * b[k];
  return s;
}
template <std::size_t n>
double norm(const std::array<double, n>& a)
{
  return std::sqrt(dot(a, a));
}
/// |a| of a 2D angle (exact), the length of a 3D rotation vector.
template <std::size_t n>
double spin_norm(const std::array<double, n>& a)
{
  if constexpr (n == 1)
    return std::abs(a[0]);
  else
    return norm(a);
}
/// |b - a| (std::hypot: no overflow, and the 2D results' bits of before).
inline double distance(const Vec2& a, const Vec2& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }
inline double distance(const Vec3& a, const Vec3& b)
{
  return std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
}
/// a x e3 for an in-plane vector a: rotates a by -90 degrees.
inline Vec2 cross_e3(const Vec2& a) { return {{a[1], -a[0]}}; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

/// The angular velocity of the skew part of a velocity gradient L
/// (2D: the e3 component; 3D: the axial vector of (L - L^T)/2).
inline Spin<2> axial_spin(const Mat2& L) { return {{0.5 * (L[2] - L[1])}}; }
inline Spin<3> axial_spin(const Mat3& L)
{
  return {{0.5 * (L[7] - L[5]), 0.5 * (L[2] - L[6]), 0.5 * (L[3] - L[1])}};
}

/// A x for a tensor A of dimension dim.
template <int dim>
Vec<dim> apply(const Mat<dim>& A, const Vec<dim>& x)
{
  Vec<dim> y;
  for (int i = 0; i < dim; ++i)
  {
    y[i] = A[i * dim] * x[0];
    for (int k = 1; k < dim; ++k)
      y[i] += A[i * dim + k] * x[k];
  }
  return y;
}
inline Vec2 apply(const Mat2& A, const Vec2& x) { return apply<2>(A, x); }
inline Vec3 apply(const Mat3& A, const Vec3& x) { return apply<3>(A, x); }

template <std::size_t dim>
std::array<double, dim * dim> outer(const std::array<double, dim>& a, const std::array<double, dim>& b)
{
  std::array<double, dim * dim> A;
  for (std::size_t i = 0; i < dim; ++i)
    for (std::size_t j = 0; j < dim; ++j)
      A[i * dim + j] = a[i] * b[j];
  return A;
}

template <int dim>
Mat<dim> matmul(const Mat<dim>& A, const Mat<dim>& B)
{
  Mat<dim> C;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j)
    {
      double s = A[i * dim] * B[j];
      for (int k = 1; k < dim; ++k)
        s += A[i * dim + k] * B[k * dim + j];
      C[i * dim + j] = s;
    }
  return C;
}
inline Mat2 matmul(const Mat2& A, const Mat2& B) { return matmul<2>(A, B); }
inline Mat3 matmul(const Mat3& A, const Mat3& B) { return matmul<3>(A, B); }

template <int dim>
Mat<dim> transpose(const Mat<dim>& A)
{
  Mat<dim> T;
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j)
      T[j * dim + i] = A[i * dim + j];
  return T;
}
inline Mat2 transpose(const Mat2& A) { return transpose<2>(A); }
inline Mat3 transpose(const Mat3& A) { return transpose<3>(A); }

inline double det(const Mat2& A) { return A[0] * A[3] - A[1] * A[2]; }
inline double det(const Mat3& A)
{
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}
inline Mat2 inverse(const Mat2& A)
{
  const double d = det(A);
  return {{A[3] / d, -A[1] / d, -A[2] / d, A[0] / d}};
}
inline Mat3 inverse(const Mat3& A)
{
  const double d = det(A);
  return {{(A[4] * A[8] - A[5] * A[7]) / d, (A[2] * A[7] - A[1] * A[8]) / d,
           (A[1] * A[5] - A[2] * A[4]) / d, (A[5] * A[6] - A[3] * A[8]) / d,
           (A[0] * A[8] - A[2] * A[6]) / d, (A[2] * A[3] - A[0] * A[5]) / d,
           (A[3] * A[7] - A[4] * A[6]) / d, (A[1] * A[6] - A[0] * A[7]) / d,
           (A[0] * A[4] - A[1] * A[3]) / d}};
}
template <std::size_t n>
double frobenius(const std::array<double, n>& A)
{
  return norm(A);
}
template <std::size_t n>
double contract(const std::array<double, n>& A, const std::array<double, n>& B)
{
  return dot(A, B);
}

/// Eigenvalues of the symmetric part, largest first.
inline Vec2 sym_eigenvalues(const Mat2& A)
{
  const double a = A[0], d = A[3], b = 0.5 * (A[1] + A[2]);
  const double m = 0.5 * (a + d), r = std::sqrt(0.25 * (a - d) * (a - d) + b * b);
  return {{m + r, m - r}};
}
/// Eigenvalues of the symmetric part, largest first (cyclic Jacobi rotations:
/// accurate to round-off also for repeated eigenvalues).
inline Vec3 sym_eigenvalues(const Mat3& A)
{
  double a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      a[i][j] = 0.5 * (A[3 * i + j] + A[3 * j + i]);
  for (int sweep = 0; sweep < 50; ++sweep)
  {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-32 * diag || off == 0.0)
      break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q)
      {
        if (a[p][q] == 0.0)
          continue;
        // rotation in the (p, q) plane that zeroes a[p][q]
        const double theta = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) // columns p, q
        {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) // rows p, q
        {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
      }
  }
  Vec3 e{{a[0][0], a[1][1], a[2][2]}};
  std::sort(e.begin(), e.end(), [](double x, double y) { return x > y; });
  return e;
}

/**
 * The rotation R of the polar decomposition F = R U (det F > 0), by Higham's
 * Newton iteration R <- (R + R^-T)/2, which converges quadratically from F.
 */
inline Mat3 polar_rotation(const Mat3& F)
{
  Mat3 R = F;
  for (int it = 0; it < 50; ++it)
  {
    const Mat3 next = 0.5 * (R + transpose(inverse(R)));
    const double change = frobenius(next - R);
    R = next;
    if (change <= 1e-14) // R is O(1)
      break;
  }
  return R;
}

/// The rotation tensor of a rotation vector (Rodrigues' formula).
inline Mat3 rotation_matrix(const Vec3& phi)
{
  const double angle = norm(phi);
  Mat3 R = identity<3>();
  if (angle == 0.0)
    return R;
  const Vec3 n = (1.0 / angle) * phi;
  const double c = std::cos(angle), s = std::sin(angle);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      R[3 * i + j] = (i == j ? c : 0.0) + (1.0 - c) * n[i] * n[j];
  R[1] -= s * n[2], R[2] += s * n[1], R[3] += s * n[2];
  R[5] -= s * n[0], R[6] -= s * n[1], R[7] += s * n[0];
  return R;
}

/// Rotation vector (axis times angle in [0, pi]) of a rotation tensor R.
inline Vec3 rotation_vector(const Mat3& R)
{
  const Vec3 s{{R[7] - R[5], R[2] - R[6], R[3] - R[1]}}; // 2 sin(angle) axis
  const double c = std::clamp(0.5 * (R[0] + R[4] + R[8] - 1.0), -1.0, 1.0);
  const double sn = 0.5 * norm(s);
  const double angle = std::atan2(sn, c);
  if (sn > 1e-8)
    return (angle / (2.0 * sn)) * s;
  if (c > 0.0)
    return 0.5 * s; // small angle: angle / sin(angle) = 1 to round-off
  // angle near pi: the axis from the symmetric part R + I = 2 n (x) n
  const Mat3 B = R + identity<3>();
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (B[i * 4] > B[k * 4])
      k = i;
  Vec3 n{{B[k], B[3 + k], B[6 + k]}};
  n = (1.0 / norm(n)) * n;
  return angle * n;
}

/**
 * The path from F0 to F1 that turns with the rotation (R(s) = exp(s log(R1
 * R0^T)) R0) and stretches linearly (U(s) = U0 + s (U1 - U0)), F = R U, for
 * s in [0, 1]: a rigid rotation stays rigid on the way, unlike F0 + s (F1 -
 * F0), which squeezes the plane normal to the axis. The polar decompositions
 * of the ends are done once; a point of the path costs one Rodrigues
 * rotation and two products.
 */
class PolarPath
{
public:
  PolarPath() = default;
  PolarPath(const Mat3& F0, const Mat3& F1)
    : F1_(F1), R0_(polar_rotation(F0)), U0_(matmul(transpose(R0_), F0))
  {
    const Mat3 R1 = polar_rotation(F1);
    U1_ = matmul(transpose(R1), F1);
    phi_ = rotation_vector(matmul(R1, transpose(R0_)));
    rotation_from = rotation_vector(R0_);
    rotation_to = rotation_vector(R1);
  }
  /// F(s) and its rotation R(s); F(1) is F1 exactly.
  void at(double s, Mat3& F, Mat3& R) const
  {
    R = matmul(rotation_matrix(s * phi_), R0_);
    F = s >= 1.0 ? F1_ : matmul(R, U0_ + s * (U1_ - U0_));
  }
  Mat3 F(double s) const
  {
    Mat3 F, R;
    at(s, F, R);
    return F;
  }
  Vec3 rotation_from{}, rotation_to{}; ///< rotation vectors of R0 and R1

private:
  Mat3 F1_ = identity<3>(), R0_ = identity<3>(), U0_ = identity<3>(), U1_ = identity<3>();
  Vec3 phi_{};
};
} // namespace fe2dem
