// The progress watchdog's rule (liggghts_fix/progress_watch.h) on its own:
// a distance that keeps falling by 10 % never stalls, one that stops falling
// stalls exactly `window` steps after its last progress, noise that only
// grazes the best does not count as progress, and window 0 is off.
#include "check.h"
#include "progress_watch.h"

#include <cmath>
#include <limits>

int main()
{
  Checker c("progress_watch");
  using fe2dem::ProgressWatch;

  // Geometric decay by 0.8 per check of 50 steps: progress at every check.
  ProgressWatch falling{1000};
  falling.start(0);
  bool ok = true;
  double d = 1e6;
  for (long step = 50; step <= 100000; step += 50, d *= 0.8) // down to 1e-188
    ok = ok && falling.progressing(d, step);
  c.truth("a distance falling by 20 % per check never stalls", ok);

  // Falls to 1e-3 by step 500, then stays there with +-5 % noise.
  ProgressWatch floor{1000};
  floor.start(0);
  long stalled_at = -1;
  for (long step = 50; step <= 5000 && stalled_at < 0; step += 50)
  {
    const double dist = step <= 500 ? std::pow(10.0, -double(step) / 250.0 * 1.5)
                                    : 1e-3 * (1.0 + 0.05 * std::sin(step));
    if (!floor.progressing(dist, step))
      stalled_at = step;
  }
  c.near("the last progress is where the fall ends (step 500)", floor.best_at, 500, 0);
  c.near("stalls exactly window steps after the last progress", stalled_at, 1500, 0);

  // Before any finite distance (no contact pass yet) the window runs from the start.
  ProgressWatch never{200};
  never.start(1000);
  const double inf = std::numeric_limits<double>::infinity();
  c.truth("still within the window at 150 steps", never.progressing(inf, 1150));
  c.truth("no finite distance in 200 steps: stalled", !never.progressing(inf, 1200));

  // Off.
  ProgressWatch off{0};
  off.start(0);
  c.truth("window 0: never stalls", off.progressing(1.0, 1000000000L));
  return c.summary();
}
