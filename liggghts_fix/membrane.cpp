// The membranes keyword membrane can name (membrane.h): one line each.
#include "membrane.h"

#include "membrane_2d.h"
#include "membrane_3d.h"

namespace fe2dem
{
std::vector<std::string> frame_membrane_names() { return {"yes", "no"}; }

template <>
std::unique_ptr<FrameMembrane<2>> make_frame_membrane<2>(const std::string& name)
{
  if (name == "yes")
    return std::make_unique<Membrane<2>>();
  return nullptr;
}

template <>
std::unique_ptr<FrameMembrane<3>> make_frame_membrane<3>(const std::string& name)
{
  if (name == "yes")
    return std::make_unique<Membrane<3>>();
  return nullptr;
}
} // namespace fe2dem
