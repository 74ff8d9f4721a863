#include "stop_request.h"

#include <csignal>

namespace fe2dem
{
namespace
{
volatile std::sig_atomic_t stop = 0; // written by a signal handler, so sig_atomic_t
}

void request_stop() noexcept
{
  stop = 1;
}

bool stop_requested() noexcept
{
  return stop != 0;
}
} // namespace fe2dem
