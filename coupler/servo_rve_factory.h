/**
 * @file servo_rve_factory.h
 * The factory of LIGGGHTS RVEs (ServoRve) behind the LIGGGHTS-free
 * interface of rve.h: what a macro code includes to get RVEs.
 */
#pragma once

#include "rve.h"
#include "rve_setup.h"

#include <memory>

namespace fe2dem
{
/**
 * RVEs built from @p setup, their trial solves starting as @p mode says.
 * Defined for dim = 2 and 3; the template's `dimension` must match.
 */
template <int dim>
std::unique_ptr<RveFactory<dim>> make_servo_rve_factory(const RveSetup& setup, HistoryMode mode);
template <>
std::unique_ptr<RveFactory<2>> make_servo_rve_factory<2>(const RveSetup& setup, HistoryMode mode);
template <>
std::unique_ptr<RveFactory<3>> make_servo_rve_factory<3>(const RveSetup& setup, HistoryMode mode);
} // namespace fe2dem
