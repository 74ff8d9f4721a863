/**
 * @file stop_request.h
 * A stop asked for by a signal (SIGTERM, SIGINT, SIGUSR1 in fe2dem), seen
 * by the RVE solves between their chunks of DEM steps: a solve that never
 * converges (or a long relaxation) no longer keeps a run from stopping. A
 * solve that sees it ends early without converging and without an error;
 * the caller must not commit it and should stop at its next collective
 * check (fe2dem: its stop signal check, then a checkpoint of the last
 * converged load step).
 */
#pragma once

#include <stdexcept>

namespace fe2dem
{
/**
 * Raised, on every rank, where a pending stop keeps RVEs from being made
 * (RvePool's constructors, after their checks): a check whose child
 * LIGGGHTS the stop's signal ended has passed without proving anything
 * (template_check.cpp), so nothing is built from what it checked.
 */
class StopRequestedError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Asks running and later RVE solves to end early. Async-signal-safe: for signal handlers.
void request_stop() noexcept;
/// Whether request_stop() was called in this process.
bool stop_requested() noexcept;
} // namespace fe2dem
