#pragma once

#include <limits>

namespace fe2dem
{
/**
 * The progress watchdog's rule, shared by fix rve/servo's solves and the
 * coupler's holds of timed solves: a solve makes progress while its distance
 * from rest (FixRveServo::distance_from_rest, 1 at rest) keeps falling below
 * 0.9 x its best; @p window DEM steps without that, and it has stalled.
 * Counted in DEM steps, so the outcome depends neither on timing nor on the
 * rank count. Pure: no LIGGGHTS.
 */
struct ProgressWatch
{
  long window = 0; ///< DEM steps without progress before a stall (stall_steps; <= 0: off)
  double best = std::numeric_limits<double>::infinity(); ///< smallest distance so far
  long best_at = 0; ///< DEM step at which best was set (or the watch started)

  /// Starts watching a solve at DEM step @p step.
  void start(long step)
  {
    best = std::numeric_limits<double>::infinity();
    best_at = step;
  }
  /// False once @p step is window steps past the last progress; @p distance as at step @p step.
  bool progressing(double distance, long step)
  {
    if (window <= 0)
      return true;
    if (distance < 0.9 * best)
    {
      best = distance;
      best_at = step;
      return true;
    }
    return step - best_at < window;
  }
};
} // namespace fe2dem
