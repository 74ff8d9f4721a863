// fix rve/servo for dimension 2 and 3: one translation unit holds the
// member definitions (the .tpp files, one job each) and instantiates them.
//   fix_rve_servo.tpp           construction, frame set-up
//   fix_rve_servo_integrate.tpp time integration, affine velocities (the frame's path:
//                               FrameMotion<dim>, frame_motion.cpp)
//   fix_rve_servo_interface.tpp fix_modify, setters, frame and particle views, f_ID
//   fix_rve_servo_input.tpp     keywords, deformation input, checks from init()
//   fix_rve_servo_solve.tpp     servo state machine and homogenisation
//   fix_rve_servo_restart.tpp   the state in restart files
//   fix_rve_servo_timed.tpp     timed solves (explicit dynamics of the macro scale)
//   fix_rve_servo_membrane.tpp  the frame membrane's side in the fix (Membrane<dim>:
//                               membrane_2d.cpp, membrane_3d.cpp)
#include "fix_rve_servo.tpp"
#include "fix_rve_servo_integrate.tpp"
#include "fix_rve_servo_interface.tpp"
#include "fix_rve_servo_input.tpp"
#include "fix_rve_servo_membrane.tpp"
#include "fix_rve_servo_restart.tpp"
#include "fix_rve_servo_solve.tpp"
#include "fix_rve_servo_timed.tpp"

namespace LAMMPS_NS
{
template class FixRveServo<2>;
template class FixRveServo<3>;
} // namespace LAMMPS_NS
