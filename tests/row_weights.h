/**
 * @file row_weights.h
 * The weights a*_IJ that the nonlocal operator should give points on a row,
 * assembled here without it (for test_nonlocal_material.cpp and
 * test_nonlocal_softening_bar.cpp): Wendland's function of the distance,
 * normalised over each row. The function itself is NonlocalOperator's,
 * checked against its closed form in test_nonlocal_operator.cpp.
 */
#pragma once

#include "nonlocal/nonlocal_operator.h"

#include <deal.II/lac/full_matrix.h>

#include <cmath>
#include <vector>

/// Row-normalised Wendland weights of the points at abscissae @p x within @p radius (0: identity).
inline dealii::FullMatrix<double> row_weights(const std::vector<double>& x, double radius)
{
  const std::size_t n = x.size();
  dealii::FullMatrix<double> W(n, n);
  for (std::size_t i = 0; i < n; ++i)
  {
    double total = 0.0;
    for (std::size_t j = 0; j < n; ++j)
      total +=
          (W(i, j) = fe2dem::macro::NonlocalOperator<2>::wendland(std::abs(x[i] - x[j]), radius));
    for (std::size_t j = 0; j < n; ++j)
      W(i, j) /= total;
  }
  return W;
}
