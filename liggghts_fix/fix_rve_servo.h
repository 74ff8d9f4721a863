/**
 * @file fix_rve_servo.h
 * LIGGGHTS fix `rve/servo`: a representative volume element (2D or 3D)
 * whose frame of boundary particles is kept periodic under a macro
 * deformation F by a servo-control loop (physics.md §2.2, §2.5), with
 * Cundall local damping of the inner particles and stress homogenisation
 * (§2.3, §2.6). The script's `dimension` chooses FixRveServo<2> or <3>.
 *
 * Syntax:
 *
 *     fix ID all rve/servo frame FRAMEGROUP cell Lx Ly [Lz] [keyword value ...]
 *
 *     F f11 f12 f21 f22        macro deformation (numbers or v_name), default I;
 *                              3D: nine values f11 f12 f13 f21 ... f33
 *     damping alpha beta       Cundall damping of force / moment, default 0.7 0.7
 *     rotation free|locked     inner-particle rotations, default free
 *     inertia disc|sphere      moment of inertia 0.5 or 0.4 m r^2, default disc (2D);
 *                              3D: sphere only
 *     gains ga gm              dimensionless servo gains g_a M/dt^2, g_m M R^2/dt^2,
 *                              default 5 10 (docs/choices.md: the paper's 100 200
 *                              diverge with our reading of the units)
 *     relax ekin_epot|unbalanced TOL   criterion (R12) or (R13), default ekin_epot 1e-3
 *     servo_tol EPS            r_a of (R14) at convergence, default 1e-4
 *     servo_scale inertia|contact  scale of r_a: inertia = (R14), residuals over
 *                              M R/dt^2 and M R^2/dt^2 ([LBS]); contact = root mean
 *                              square over pairs and corners, over the rms contact
 *                              force f (moments over f R), so that EPS is a fraction
 *                              of a typical contact force at any pressure. Default inertia
 *     check_every N            steps between convergence checks, default 50
 *     max_steps N              step budget of one solve, default 2000000
 *     stall_steps N            progress watchdog: a solve whose distance from
 *                              convergence, max(r_a/servo_tol, relaxation measure/TOL),
 *                              has not fallen below 0.9 x its best for N DEM steps
 *                              fails as stalled; 0: off. Default 1000000
 *     start keep|reset         keep or reset frame fluctuations at a new F, default keep
 *     inner_start keep|affine  at a new F the inner particles start where they are and
 *                              follow the frame through contacts (keep, [LBS]), or move
 *                              with the affine velocity field of F_old -> F while the
 *                              frame moves (affine; tangential springs see it), default keep
 *     move_rate FRAC           largest frame move per step / R_min, default 1e-3
 *     on_failure error|flag    stop LIGGGHTS or only set the status, default error
 *     max_overlap FRAC         largest contact overlap / smaller radius, in the
 *                              packing as read and at every contact evaluation of a
 *                              solve (beyond it: error, or status overlapped), default 0.5
 *     membrane yes|no          frame membrane: keeps inner particles from slipping
 *                              through gaps that open when the frame stretches. 2D: an
 *                              inner particle whose centre comes closer than its
 *                              radius to the line between two neighbouring frame
 *                              particles is pushed back with the normal contact
 *                              force, the reaction going to those two frame particles
 *                              (and so into P). 3D: the same with the Delaunay
 *                              triangles of each face's frame particles, acting once
 *                              a centre crosses a triangle's plane
 *                              (membrane_3d.h). Needs kn or Debian's
 *                              hertz model. Default yes (docs/choices.md)
 *     timed_servo integral|proportional  the frame servo of timed solves: with integral
 *                              action (each correction also carries the running mean of
 *                              the recent ones, so a steady drift of the balanced
 *                              fluctuations is followed without a steady imbalance) or
 *                              proportional (issue 18; the frame lags by an amount that
 *                              grows with the loading rate). Default integral. A group
 *                              none of whose images touches anything holds still and
 *                              forgets its drift (anti-windup: else it coasts out of the
 *                              cell; servo_controller.cpp)
 *
 * `fix_modify ID F f11 f12 f21 f22` (3D: nine values) starts a new solve under a new F;
 * `fix_modify ID max_steps N` changes the step budget (not kept in restarts). The
 * solve advances while the script (or C++) runs steps; f_ID[1] is the status.
 * `fix_modify ID timed_steps N` (N a multiple of check_every; 0: off, the default;
 * not kept in restarts) makes later solves timed, for explicit dynamics of the
 * macro scale: exactly N steps, the frame moving check by check along the
 * straight path of F plus w, the servo correcting w at every check as a
 * continuous feedback, no convergence stop, the frame at rest after the last
 * check until the next F; P and the stresses are their means over the solve's checks
 * (fix_rve_servo_timed.tpp). `fix_modify ID timed_stress mean|last` (default mean;
 * not kept in restarts): what a timed solve reports, the mean over its checks (a
 * box filter, delayed by (c - 1)/(2c) of the solve for c checks) or its last check's,
 * the state at the new F. An explicit macro step needs last: there a delayed
 * stiffness feeds energy into the motion (benchmarks/dynamics_filter).
 *
 * The fix integrates every particle itself (do not add fix nve/sphere):
 * inner particles by velocity Verlet with local damping, frame particles by
 * prescribed velocities so that tangential contact history sees the motion.
 *
 * One physical contact, one count (physics.md §2.1): a contact between two
 * frame particles that are both +Lx images (or both +Ly, +Lz images) is the
 * second copy of the contact between their originals. The fix puts the images
 * into groups ID_image_x, ID_image_y (, ID_image_z) and excludes pairs inside
 * each group from LIGGGHTS' neighbour lists (two or three of LIGGGHTS' 32
 * groups), so every force,
 * stress, energy and statistic holds each physical contact once; coordination
 * counts each physical particle once.
 *
 * The whole fix state (reference frame, servo unknowns, frame motion, last
 * results) goes into restart files: write_restart / read_restart and
 * re-issuing the same fix command continue a solve bit for bit.
 *
 * Conventions: tension positive; tensors row-major ({11, 12, 21, 22} in 2D,
 * {11, 12, 13, 21, ..., 33} in 3D); frame forces a_q are the forces the frame
 * applies to particle q. Requires `atom_modify map array`, `atom_style
 * sphere`, a granular pair style, and the fix defined before the first run.
 */
#ifdef FIX_CLASS
// Registered at run time by fe2dem::register_styles(), not by LIGGGHTS' style_fix.h.
#else

#ifndef FE2DEM_FIX_RVE_SERVO_H
#define FE2DEM_FIX_RVE_SERVO_H

#include "atom.h"
#include "fix.h"
#include "frame_motion.h"
#include "membrane.h"
#include "progress_watch.h"
#include "rve_homogenisation.h"
#include "servo_controller.h"

#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS
{
template <int dim>
class FixRveServo : public Fix
{
public:
  using Vector = fe2dem::Vec<dim>;
  using Tensor = fe2dem::Mat<dim>;
  using Rotation = fe2dem::Spin<dim>; ///< angle (2D) or rotation vector (3D)
  static constexpr int n_tensor = dim * dim;
  static constexpr int n_spin = dim == 2 ? 1 : 3;

  /// Outcome of the current solve. Values are those of f_ID[1].
  enum Status
  {
    running = 0,
    converged = 1,
    over_budget = 2,     ///< max_steps reached without convergence
    escaped = 3,         ///< an inner particle left the frame
    blown_up = 4,        ///< non-finite position, velocity or force
    overlapped = 5,      ///< a contact overlaps beyond max_overlap
    stalled = 6          ///< no progress towards convergence for stall_steps steps
  };

  /**
   * The global vector f_ID[k + 1] = compute_vector(k), by name (table in docs/fix-rve-servo.md).
   * Tensors take dim^2 consecutive entries, row-major (2D: 4, 3D: 9).
   */
  enum Output : int
  {
    out_status = 0,
    out_servo_iterations = 1,
    out_dem_steps = 2,
    out_residual = 3,
    out_ekin_epot = 4,
    out_unbalanced = 5,
    out_P = 6,
    out_sigma = out_P + n_tensor,
    out_sigma_lw = out_sigma + n_tensor,
    out_F_check = out_sigma_lw + n_tensor,
    out_coordination = out_F_check + n_tensor,
    out_mechanical_coordination,
    out_anisotropy,
    out_packing_fraction, ///< 3D: solid volume fraction
    out_sliding_contacts,
    out_max_overlap,
    out_contacts,
    out_max_inner_omega,
    out_fabric,
    out_F = out_fabric + n_tensor,
    out_membrane_steps = out_F + n_tensor,
    out_fabric_deviator, ///< fe2dem::fabric_deviator of the fabric
    out_size ///< length of the vector (2D: 40, 3D: 70)
  };

  /// Everything a solve returns; updated at every convergence check.
  struct Result
  {
    Tensor F = fe2dem::identity<dim>(), F_check = fe2dem::identity<dim>();
    Tensor P{}, sigma{}, sigma_lw{};
    double residual = 0.0;        ///< r_a (R14)
    double ekin_epot = 0.0;       ///< (R12) over inner particles
    double unbalanced = 0.0;      ///< (R13)
    double packing_fraction = 0.0;
    double max_inner_omega = 0.0; ///< max |omega| of inner particles
    int servo_iterations = 0;
    long dem_steps = 0;           ///< steps of this solve
    long membrane_steps = 0;      ///< particle-steps of this solve with a membrane contact
    fe2dem::ContactStatistics<dim> contacts;
  };

  FixRveServo(class LAMMPS*, int, char**);
  ~FixRveServo() override;
  int setmask() override;
  void post_create() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void final_integrate() override;
  void end_of_step() override;
  int modify_param(int, char**) override;
  double compute_vector(int) override;
  double memory_usage() override;
  void write_restart(FILE*) override;
  void restart(char*) override;

  /// Starts a new solve under macro deformation F (row-major), as `fix_modify ID F` does.
  void set_deformation(const Tensor& F);
  /// Step budget of the solves from now on, as `fix_modify ID max_steps` sets it. @pre n >= 1.
  void set_max_steps(long n);
  /**
   * Timed solves from the next F on (explicit dynamics), as `fix_modify ID
   * timed_steps` sets it: each runs exactly @p n DEM steps, n dt of physical
   * time, and reports the mean stresses of its checks. 0: quasi-static solves.
   * @pre n = 0 or a positive multiple of check_every (else a LIGGGHTS error).
   */
  void set_timed_steps(long n);
  long timed_steps() const { return timed_steps_; }
  /// What a timed solve reports, as `fix_modify ID timed_stress` sets it: the mean of its checks' P and
  /// stresses (true, the default) or those of its last check (false).
  void set_timed_mean(bool mean) { timed_mean_ = mean; }
  bool timed_mean() const { return timed_mean_; }
  Status status() const { return status_; }
  static const char* status_name(Status s);
  const Result& result() const { return result_; }
  const fe2dem::FrameTopology<dim>& frame() const { return frame_; }
  /// Current frame positions relative to the cell origin, in frame order.
  std::vector<Vector> frame_positions() const;
  /// Forces a_q the frame applied in the last step, in frame order.
  const std::vector<Vector>& frame_forces() const { return frame_force_; }
  /// Frame fluctuations w per group (edge pair in 2D; face pair or edge group in 3D).
  const std::vector<Vector>& fluctuations() const { return servo_.w; }
  /// Current rotation of each frame particle, in frame order.
  const std::vector<Rotation>& frame_rotations() const { return motion_.rotations(); }
  /**
   * Mean over the inner particles of |theta|, theta the rotation each has
   * accumulated since the fix was set up on the packing (the integral of
   * its spin, midpoint rule; an angle in 2D, a rotation vector's length in
   * 3D), in rad. Restart files carry it, so it survives commits, rollbacks
   * and moves between ranks. A mean of lengths: the difference between two
   * solves is the rotation in between only where that rotation dominates
   * the earlier one (as in a shear band; a rigid rotation adds exactly).
   */
  double mean_rotation() const;
  /**
   * The convergence test of a quasi-static solve (relaxed by the relaxation
   * criterion, frame balanced within servo_tol) on the state the last check
   * homogenised: for drivers that end timed solves themselves, e.g. a frame
   * held at one F by timed solves until it is at rest (coupler/servo_rve.h,
   * continuous solve drive).
   */
  bool at_rest() const;
  /**
   * How far the state the last check homogenised is from at_rest(): the
   * larger of r_a / servo_tol and the relaxation measure / its tolerance
   * (at most 1 when at rest; infinite before the first contact pass). The
   * progress watchdog's measure, for drivers of timed solves as well.
   */
  double distance_from_rest() const;
  /// Steps without progress after which a solve fails as stalled (keyword stall_steps; 0: off).
  long stall_steps() const { return progress_.window; }
  /// Steps of the current frame move still to run (0: the frame is at rest).
  int frame_move_steps_left() const { return motion_.steps_left(); }
  /// Steps between checks: C++ drivers run chunks of this length.
  int check_interval() const { return check_every_; }
  /// Step budget of one solve (keyword max_steps, fix_modify max_steps).
  long max_steps() const { return max_steps_; }
  /// One particle as output sees it (particle pictures, force chains).
  struct Particle
  {
    int tag = 0;
    Vector x{};  ///< current centre
    double radius = 0.0;
    bool frame = false; ///< boundary (frame) particle
  };
  /// All particles, indexed like Contact::i and Contact::j of contacts().
  std::vector<Particle> particles() const;
  /// Contacts found at the last convergence check (end of the last solve).
  const std::vector<fe2dem::Contact<dim>>& contacts() const { return contacts_; }
  /// Human-readable reason of the last failure (empty if none).
  const std::string& failure_reason() const { return failure_reason_; }

private:
  // --- input -------------------------------------------------------------
  void parse_arguments(int narg, char** arg);
  void parse_deformation(char** arg, const char* where);
  void error_checks();
  Tensor evaluate_deformation();
  /// @p F if finite with det F > 0, else an error naming keyword F.
  Tensor checked_deformation(const Tensor& F);
  void lookup_contact_law();

  // --- servo state machine ----------------------------------------------
  /// Starts a solve under @p F, or under keyword F's values if null.
  void begin_solve(const Tensor* F = nullptr);
  /// Starts the frame's move to its targets for F_ after it was at @p F_from (servo moves: F_).
  void schedule_frame_move(const Tensor& F_from);
  /// Kinetic energy of the inner particles; flags escape and blow-up.
  double check_particles();
  /// Contacts, stresses, statistics and servo residual into result_.
  void homogenise(double ekin);
  /// Relaxation test, convergence decision or servo correction at a check.
  void servo_check(double ekin);
  /// Progress watchdog at a check with the frame at rest: false (and the
  /// solve failed as stalled) after stall_steps steps without progress.
  bool progressing(double residual, double ekin);
  /// distance_from_rest() for a servo residual @p residual and inner kinetic energy @p ekin.
  double distance_from_rest(double residual, double ekin) const;
  /// The relaxation criterion (relax ekin_epot | unbalanced) with contact statistics @p c.
  bool relaxed_with(const fe2dem::ContactStatistics<dim>& c, double ekin) const;
  double servo_residual() const;
  /// Sum of a per-frame-particle value over the images of group @p g.
  template <class T>
  static T group_sum(const std::vector<T>& per_particle, const typename fe2dem::FrameTopology<dim>::Group& g)
  {
    using fe2dem::operator+;
    T sum = per_particle[g[0]];
    for (std::size_t m = 1; m < g.size() && g[m] >= 0; ++m)
      sum = sum + per_particle[g[m]];
    return sum;
  }
  /// No frame particle of @p images (frame indices; -1 entries skipped) has a force or torque.
  template <class Indices>
  bool untouched(const Indices& images) const;
  /// A servo correction of the frame's unknowns (step 4), then the frame's move to them.
  void apply_servo_correction();
  /// The servo correction alone: the gains, their adaptation and the integral action.
  void correct_servo();
  void fail(Status s, const std::string& reason);
  // --- timed solves (fix_rve_servo_timed.tpp) ------------------------------
  void begin_timed_solve(const Tensor& F_before);
  /// Velocity gradient of the mean motion F_before -> F of a timed solve at its current step.
  Tensor timed_velocity_gradient() const;
  /// The mean motion's F after @p step DEM steps of a timed solve (F_ at its end).
  Tensor timed_deformation(long step) const;
  /// The frame's move of the check that starts at DEM step @p step of a timed solve.
  void schedule_timed_segment(long step);
  /// A check of a timed solve: homogenise, filter, finish at its last step.
  void timed_check(long step);
  /// The contact of contacts_ with the largest overlap, for messages.
  std::string describe_largest_overlap() const;
  /// Stops with an error if the packing's centres do not fit the dimension (z = 0 in 2D).
  void check_packing_dimension();
  /// Stops with an error naming the pair if the packing as read overlaps beyond max_overlap.
  void check_reference_overlaps();

  // --- helpers ------------------------------------------------------------
  int local_index(int tag) const;
  /// Leaves the second copy of every frame-frame contact out of LIGGGHTS' neighbour lists.
  void exclude_duplicate_contacts();
  /// Fills physical_of_ from the frame topology (frame images -> one particle).
  void map_physical_particles();
  void collect_contacts();
  void create_contacts_compute();
  template <class Stream>
  void transfer_state(Stream& s, std::uint32_t version);
  void half_kick_inner(bool drift);
  /// inner_start affine: adds / removes the affine velocity of the inner particles.
  void add_affine_velocity();

  void remove_affine_velocity();

  // --- frame membrane (membrane_2d.h, membrane_3d.h) -----------------------
  /// The membrane's segments (2D) or triangles (3D) from the frame.
  void build_membrane();
  /// Adds membrane forces to inner and frame particles (before frame forces are recorded).
  void apply_membrane();
  /// Particle i is an inner particle the fix integrates (in its group, not in the frame).
  bool is_inner(int i) const
  {
    return (atom->mask[i] & groupbit) && !(atom->mask[i] & frame_groupbit_);
  }
  /// Moment of inertia of particle i (disc or sphere factor).
  double inertia_of(int i) const
  {
    return inertia_factor_ * atom->rmass[i] * atom->radius[i] * atom->radius[i];
  }

  // parameters
  std::string frame_group_;
  int frame_groupbit_ = 0;
  Vector L_{}; ///< keyword cell
  std::vector<std::string> F_input_; // dim^2 entries: numbers or v_names
  double alpha_ = 0.7, beta_ = 0.7;
  bool lock_rotation_ = false;
  double inertia_factor_ = dim == 2 ? 0.5 : 0.4;
  bool criterion_unbalanced_ = false;
  double relax_tol_ = 1e-3;
  double servo_tol_ = 1e-4;
  bool servo_scale_contact_ = false; ///< servo_scale contact (else inertia, R14)
  int check_every_ = 50;
  long max_steps_ = 2000000;
  bool keep_fluctuations_ = true;
  bool affine_inner_ = false; ///< inner_start affine
  double move_rate_ = 1e-3;
  bool error_on_failure_ = true;
  bool timed_integral_ = true; ///< timed_servo integral (else proportional)
  double max_overlap_ = 0.5;

  // frame
  fe2dem::FrameTopology<dim> frame_;
  double r_min_ = 0.0, r_max_ = 0.0;
  double area_particles_ = 0.0; ///< particle area (3D: volume) inside the periodic cell
  fe2dem::ContactLaw law_;

  // the servo's unknowns (fluctuation and rotation per group, the corners'
  // rotation), its gains and its memory (servo_controller.h)
  fe2dem::ServoController<dim> servo_;

  // the frame's prescribed motion and rotations (frame_motion.h)
  fe2dem::FrameMotion<dim> motion_;
  std::vector<Vector> affine_velocity_; ///< per local index, added this step
  Rotation affine_spin_{};

  // per-step records
  std::vector<int> frame_local_;      ///< local index of each frame particle
  /// keyword membrane (membrane.h; made as the keyword is read); null: none
  std::unique_ptr<fe2dem::FrameMembrane<dim>> membrane_ = fe2dem::make_frame_membrane<dim>("yes");
  std::vector<Vector> frame_force_;   ///< a_q
  std::vector<Rotation> frame_moment_; ///< m_q
  double unbalanced_sq_sum_ = 0.0;

  // solve state
  Tensor F_ = fe2dem::identity<dim>();
  Status status_ = running;
  bool solve_pending_ = true;
  std::string failure_reason_;
  Result result_;
  class Compute* contacts_compute_ = nullptr;
  std::string contacts_compute_id_;
  std::vector<fe2dem::Contact<dim>> contacts_;
  std::vector<int> tag_to_dense_;
  std::vector<Rotation> rotation_; ///< accumulated rotation per dense index (inner particles)
  int n_particles_ = 0;           ///< RVE bodies (frame images counted separately)
  std::vector<int> physical_of_;  ///< dense index -> dense index of its physical particle
  int n_inner_ = 0;
  int checks_since_contact_pass_ = 0;
  fe2dem::ProgressWatch progress_{1000000}; ///< the progress watchdog of the current solve (stall_steps)
  double dtv_ = 0.0, dtf_ = 0.0;
  bool restored_ = false; ///< state came from a restart file

  // timed solves: DEM steps per solve (0: quasi-static), the mean or the last check, the box filter's sums
  long timed_steps_ = 0;
  bool timed_mean_ = true;
  int timed_samples_ = 0;
  Tensor timed_P_sum_{}, timed_sigma_sum_{}, timed_sigma_lw_sum_{};
  Tensor timed_F_from_ = fe2dem::identity<dim>(); ///< F at the start of the timed solve
};
} // namespace LAMMPS_NS

#endif
#endif
