#include "register_styles.h"

#include "domain.h"
#include "fix_rve_servo.h"
#include "lammps.h"
#include "modify.h"

#include <map>
#include <string>

namespace
{
// Modify::fix_map is private and LIGGGHTS offers no plugin API. An explicit
// template instantiation may name a private member (C++17 [temp.explicit]/12),
// which yields a pointer-to-member without touching LIGGGHTS' sources.
using FixCreator = LAMMPS_NS::Fix* (*)(LAMMPS_NS::LAMMPS*, int, char**);
using FixMap = std::map<std::string, FixCreator>;

struct ModifyFixMap
{
  using type = FixMap* LAMMPS_NS::Modify::*;
  friend type member(ModifyFixMap);
};

template <typename Tag, typename Tag::type Member>
struct ExposeMember
{
  friend typename Tag::type member(Tag) { return Member; }
};
template struct ExposeMember<ModifyFixMap, &LAMMPS_NS::Modify::fix_map>;

/// fix rve/servo in the script's dimension (set before any fix can be defined).
LAMMPS_NS::Fix* create_rve_servo(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg)
{
  if (lmp->domain->dimension == 3)
    return new LAMMPS_NS::FixRveServo<3>(lmp, narg, arg);
  return new LAMMPS_NS::FixRveServo<2>(lmp, narg, arg);
}
} // namespace

namespace fe2dem
{
void register_styles(LAMMPS_NS::LAMMPS* lmp)
{
  FixMap* map = lmp->modify->*member(ModifyFixMap{});
  (*map)["rve/servo"] = &create_rve_servo;
}
} // namespace fe2dem
