/**
 * @file output_lock.h
 * One writer per output directory: an exclusive flock(2) on
 * OUTPUT/.fe2dem.lock, held from before anything in the directory is
 * truncated until the process ends. The kernel drops it when the holder
 * dies (even by SIGKILL), so a crashed run never blocks the next one. The
 * file holds the holder's host and PID, for the message. fe2dem and
 * fe2dem-rve both take it.
 */
#pragma once

#include <string>

namespace fe2dem
{
class OutputLock
{
public:
  /**
   * Takes the lock of @p directory (which must exist).
   * @throws std::runtime_error naming the directory and the holder if
   *         another process holds it, or if the lock file cannot be made.
   */
  explicit OutputLock(const std::string& directory);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

private:
  int fd_ = -1;
};
} // namespace fe2dem
