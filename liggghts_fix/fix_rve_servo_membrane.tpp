// The frame membrane of fix rve/servo (keyword membrane): the fix's side of
// it. The membrane the keyword names (make_frame_membrane, membrane.cpp:
// Membrane<2> of membrane_2d.h, Membrane<3> of membrane_3d.h) holds the
// geometry and the forces; here it gets the atoms and the frame's state.
#pragma once

#include "fix_rve_servo.h"

#include "error.h"
#include "neighbor.h"

#include <stdexcept>

using namespace LAMMPS_NS;

template <int dim>
void FixRveServo<dim>::build_membrane()
{
  if (!membrane_)
    return;
  try
  {
    membrane_->build(frame_, L_);
  }
  catch (const std::exception& e)
  {
    error->fix_error(FLERR, this, e.what());
  }
}

template <int dim>
void FixRveServo<dim>::apply_membrane()
{
  if (!membrane_ || !law_.has_normal_stiffness())
    return;
  const fe2dem::MembraneStep<dim> step{atom->x,       atom->f,   atom->radius, atom->mask,
                                       atom->nlocal,  groupbit,  frame_groupbit_, neighbor->skin,
                                       neighbor->lastcall, frame_, frame_local_, F_,
                                       r_max_,        law_};
  result_.membrane_steps += membrane_->apply(step);
}
