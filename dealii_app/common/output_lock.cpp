#include "output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace fe2dem
{
void make_output_directory(const std::string& directory, const std::string& named_as)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  for (fs::path p = fs::path(directory).lexically_normal(); !p.empty(); p = p.parent_path())
  {
    if (fs::exists(p, ec) && !fs::is_directory(p, ec))
      throw std::runtime_error(named_as + ": '" + p.string() + "' is a file, not a directory; name a "
                               "directory for the output (it is created if missing)");
    if (p == p.parent_path())
      break;
  }
  fs::create_directories(directory, ec);
  if (ec)
    throw std::runtime_error(named_as + ": cannot create '" + directory + "' (" + ec.message() +
                             "); choose a writable directory");
}

OutputLock::OutputLock(const std::string& directory)
{
  const std::string file = directory + "/.fe2dem.lock";
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error("cannot create the lock file '" + file + "' (" + std::strerror(errno) +
                             "): choose a writable 'Output directory'");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0)
  {
    char holder[256] = {};
    const ssize_t n = ::pread(fd_, holder, sizeof holder - 1, 0);
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("'Output directory' = '" + directory + "' is in use by another fe2dem or fe2dem-rve run (" +
                             (n > 0 ? std::string(holder, static_cast<std::size_t>(n)) : "holder unknown") +
                             ", lock file " + file + "): wait for it to end, or choose another "
                             "'Output directory'; nothing in the directory was changed");
  }
  char host[128] = {};
  ::gethostname(host, sizeof host - 1);
  const std::string who = "process " + std::to_string(::getpid()) + " on " + host;
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, who.data(), who.size(), 0) < 0)
    return; // the lock holds; only the holder's name for others' messages is missing
}

OutputLock::~OutputLock()
{
  if (fd_ >= 0)
    ::close(fd_); // releases the flock
}
} // namespace fe2dem
