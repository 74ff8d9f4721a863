/**
 * @file quiet_stdout.h
 * RAII redirection of the process' stdout to /dev/null, used around the
 * construction of a LIGGGHTS instance: Debian's build prints hundreds of
 * "Style collision" warnings there that users must not see.
 */
#pragma once

#include <cstdio>
#include <fcntl.h>
#include <unistd.h>

namespace fe2dem
{
class QuietStdout
{
public:
  QuietStdout()
  {
    std::fflush(stdout);
    saved_ = dup(STDOUT_FILENO);
    const int null_fd = open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null_fd >= 0)
      dup2(null_fd, STDOUT_FILENO);
    if (null_fd >= 0)
      close(null_fd);
  }
  ~QuietStdout()
  {
    std::fflush(stdout);
    if (saved_ >= 0)
    {
      dup2(saved_, STDOUT_FILENO);
      close(saved_);
    }
  }
  QuietStdout(const QuietStdout&) = delete;
  QuietStdout& operator=(const QuietStdout&) = delete;

private:
  int saved_ = -1;
};
} // namespace fe2dem
