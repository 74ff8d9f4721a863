/**
 * @file quiet_output.h
 * RAII redirection of the process' stdout and stderr to /dev/null around
 * LIGGGHTS calls that print Debian's "Style collision" warnings (instance
 * construction, style-defining commands of a second instance). Users must
 * not see them; LIGGGHTS' own messages go to its screen/log files instead.
 */
#pragma once

#include <cstdio>
#include <fcntl.h>
#include <unistd.h>

namespace fe2dem
{
class QuietOutput
{
public:
  QuietOutput()
  {
    std::fflush(stdout);
    std::fflush(stderr);
    const int null_fd = open("/dev/null", O_WRONLY);
    for (int k = 0; k < 2; ++k)
    {
      saved_[k] = dup(fds_[k]);
      if (saved_[k] >= 0 && null_fd >= 0)
        dup2(null_fd, fds_[k]);
    }
    if (null_fd >= 0)
      close(null_fd);
  }
  ~QuietOutput()
  {
    std::fflush(stdout);
    std::fflush(stderr);
    for (int k = 0; k < 2; ++k)
      if (saved_[k] >= 0)
      {
        dup2(saved_[k], fds_[k]);
        close(saved_[k]);
      }
  }
  QuietOutput(const QuietOutput&) = delete;
  QuietOutput& operator=(const QuietOutput&) = delete;

private:
  const int fds_[2] = {STDOUT_FILENO, STDERR_FILENO};
  int saved_[2] = {-1, -1};
};
} // namespace fe2dem
