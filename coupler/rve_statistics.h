/**
 * @file rve_statistics.h
 * The one list of per-IP statistics an RVE returns besides F, P and sigma.
 * Every consumer walks this list: the RVE pool's transport between ranks,
 * fe2dem's IP state, its checkpoints and history.h5 (a dataset per entry,
 * with the unit and description given here). A new statistic is one line
 * below (its source expression reads the fix's result in servo_rve.cpp).
 *
 * Columns: kind (tensor: dim x dim, row-major {11, 12, 21, 22}; scalar:
 * double; count: integer), name (history.h5 dataset), unit, description,
 * source (an expression on `r`, the fix's FixRveServo<dim>::Result, or on
 * `fix_`, the fix itself; expanded only on the LIGGGHTS side of the
 * coupler, ServoRve::response() in servo_rve.cpp).
 * Conventions: tension positive; stresses in `stress_unit`: force per length
 * (N/m) in 2D, per area (Pa) in 3D.
 */
#pragma once

#include <array>
#include <cstddef>

// clang-format off
#define FE2DEM_RVE_STATISTICS(X)                                                                     \
  X(tensor, fabric, "1", "fabric tensor Pi = (1/C) sum_c n_c (x) n_c (physics.md 2.6)", r.contacts.fabric) \
  X(scalar, coordination, "1", "coordination number 2C/N over physical particles", r.contacts.coordination) \
  X(scalar, anisotropy, "1", "fabric anisotropy Pi_1/Pi_2 - 1", r.contacts.anisotropy)               \
  X(count, servo_iterations, "1", "servo corrections of the last solve", r.servo_iterations)        \
  X(count, dem_steps, "1", "DEM steps of the last solve (0 if it was skipped)", r.dem_steps)         \
  X(tensor, sigma_lw, stress_unit, "Love-Weber stress of the contacts (R8), tension positive", r.sigma_lw)  \
  X(scalar, mechanical_coordination, "1", "(2C - N1)/(N - N0 - N1) (Thornton)",                        \
    r.contacts.mechanical_coordination)                                                               \
  X(scalar, packing_fraction, "1", "solid area fraction of the periodic cell", r.packing_fraction)   \
  X(scalar, residual, "1", "servo residual r_a (R14) at the end of the solve", r.residual)           \
  X(scalar, ekin_epot, "1", "E_kin/E_pot of the inner particles (R12) at the end of the solve", r.ekin_epot) \
  X(scalar, mean_overlap, "1", "mean contact overlap / smaller radius", r.contacts.mean_overlap)    \
  X(scalar, max_overlap, "1", "largest contact overlap / smaller radius", r.contacts.max_overlap)    \
  X(count, contacts, "1", "contacts C (pairs with positive overlap) at the end of the solve",         \
    r.contacts.n_contacts)                                                                            \
  X(count, sliding_contacts, "1", "contacts at the Coulomb limit |f_s| = mu |f_n| (-1: mu unknown)",  \
    r.contacts.n_sliding)                                                                             \
  X(scalar, fabric_deviator, "1", "sqrt(dim/(dim-1) Pi':Pi')/tr Pi: 0 isotropic, 1 along one axis",   \
    fe2dem::fabric_deviator(r.contacts.fabric))                                                       \
  X(count, membrane_steps, "1", "particle-steps of the last solve with a membrane contact",          \
    r.membrane_steps)                                                                                 \
  X(scalar, F_check_error, "1", "|F_check - F|/|F|: F measured on the frame against the imposed F",   \
    fe2dem::frobenius(r.F_check - r.F) / fe2dem::frobenius(r.F))                                      \
  X(scalar, mean_rotation, "rad",                                                                     \
    "mean |rotation| of the inner particles accumulated since the RVE was built (from its spin)",    \
    fix_->mean_rotation())
// clang-format on

namespace fe2dem
{
namespace detail
{
template <int dim, int kind>
struct StatisticType;
enum StatisticKind
{
  tensor,
  scalar,
  count
};
template <int dim>
struct StatisticType<dim, tensor>
{
  using type = std::array<double, dim * dim>;
};
template <int dim>
struct StatisticType<dim, scalar>
{
  using type = double;
};
template <int dim>
struct StatisticType<dim, count>
{
  using type = long;
};
} // namespace detail

/// The statistics of FE2DEM_RVE_STATISTICS as members, zero-initialised.
template <int dim>
struct RveStatistics
{
  /// The unit of the stress entries (and of F, P, sigma beside them).
  static constexpr const char* stress_unit = dim == 2 ? "N/m" : "Pa";
#define FE2DEM_MEMBER(kind, name, unit, description, source)                                        \
  typename detail::StatisticType<dim, detail::kind>::type name{};
  FE2DEM_RVE_STATISTICS(FE2DEM_MEMBER)
#undef FE2DEM_MEMBER

  /**
   * Calls @p visit(name, unit, description, value) for every statistic in
   * list order; value is a (const) reference to the member, so one visitor
   * with overloads for std::array<double, dim*dim>, double and long reads
   * or writes them all.
   */
  template <class Visitor>
  void for_each(Visitor&& visit)
  {
#define FE2DEM_VISIT(kind, name, unit, description, source) visit(#name, unit, description, name);
    FE2DEM_RVE_STATISTICS(FE2DEM_VISIT)
#undef FE2DEM_VISIT
  }
  template <class Visitor>
  void for_each(Visitor&& visit) const
  {
#define FE2DEM_VISIT(kind, name, unit, description, source) visit(#name, unit, description, name);
    FE2DEM_RVE_STATISTICS(FE2DEM_VISIT)
#undef FE2DEM_VISIT
  }

  /// Number of doubles of pack().
  static constexpr std::size_t packed_size()
  {
    std::size_t n = 0;
#define FE2DEM_SIZE(kind, name, unit, description, source)                                          \
  n += detail::kind == detail::tensor ? dim * dim : 1;
    FE2DEM_RVE_STATISTICS(FE2DEM_SIZE)
#undef FE2DEM_SIZE
    return n;
  }

  /// Writes packed_size() doubles at @p out (counts exactly: they stay below 2^53).
  double* pack(double* out) const
  {
    for_each([&](const char*, const char*, const char*, const auto& v) { out = put(v, out); });
    return out;
  }
  /// Reads what pack() wrote; returns the position after it.
  const double* unpack(const double* in)
  {
    for_each([&](const char*, const char*, const char*, auto& v) { in = get(v, in); });
    return in;
  }

private:
  static double* put(const std::array<double, dim * dim>& t, double* out)
  {
    for (double x : t)
      *out++ = x;
    return out;
  }
  static double* put(double x, double* out)
  {
    *out++ = x;
    return out;
  }
  static double* put(long n, double* out)
  {
    *out++ = static_cast<double>(n);
    return out;
  }
  static const double* get(std::array<double, dim * dim>& t, const double* in)
  {
    for (double& x : t)
      x = *in++;
    return in;
  }
  static const double* get(double& x, const double* in)
  {
    x = *in++;
    return in;
  }
  static const double* get(long& n, const double* in)
  {
    n = static_cast<long>(*in++);
    return in;
  }
};
} // namespace fe2dem
