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
/**
 * Creates @p directory (and its parents) if missing.
 * @param named_as how the user gave it, for the message (e.g. "'Output
 *        directory' = '...'" or "--output-directory ...").
 * @throws std::runtime_error naming it if it, or a parent, is a file, or if
 *         it cannot be created (with the system's reason).
 */
void make_output_directory(const std::string& directory, const std::string& named_as);

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
