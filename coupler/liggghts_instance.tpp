// Template part of liggghts_instance.h.
#include "fix.h"

#include <stdexcept>

namespace fe2dem
{
template <class T>
T& LiggghtsInstance::fix(const std::string& id)
{
  T* f = dynamic_cast<T*>(static_cast<LAMMPS_NS::Fix*>(find_fix(id)));
  if (f == nullptr)
    throw std::runtime_error("LIGGGHTS fix '" + id + "' is missing or has an unexpected style");
  return *f;
}
} // namespace fe2dem
