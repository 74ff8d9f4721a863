/**
 * @file macro_parameters.h
 * Parameters of `fe2dem FILE.prm`, one struct per subsection in the deal.II
 * tutorial style (step-44): declare_parameters() documents every entry with
 * a pattern, parse_parameters() reads and checks it.
 */
#pragma once

#include "rve_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace fe2dem::macro
{
/**
 * subsection Geometry: a subdivided box [0, width] x [0, height] (x [0, depth]
 * in 3D), or a mesh file. y is the vertical (loading) axis in both dimensions.
 */
struct Geometry
{
  unsigned int dimension; ///< 2 (plane strain, quadrilaterals) or 3 (hexahedra)
  double width, height, depth;
  unsigned int nx, ny, nz;
  double distortion;     ///< random interior node shift / cell size (patch tests)
  std::string mesh_file; ///< Gmsh (.msh) or UCD (.inp, .ucd) file; empty: the rectangle
  static void declare_parameters(dealii::ParameterHandler& prm);
  /// @param base directory of the parameter file (relative mesh paths).
  void parse_parameters(dealii::ParameterHandler& prm, const std::string& base);
};

/// subsection Material: the built-in compressible neo-Hookean law.
struct MaterialParameters
{
  enum class Type
  {
    neo_hookean,
    rve
  } type;
  double shear_modulus, lame_lambda, density;
  double stability_modulus; ///< RVE: upper estimate of the tangent modulus (stable step)
  HistoryMode history;      ///< RVE: where trial solves start
  double skip_tolerance;    ///< RVE: reuse the last response if |F - F_last| below it (0: off)
  long steps_per_iteration; ///< RVE: DEM steps per DR iteration before convergence (0: relax fully)
  double initial_pressure;  ///< RVE: each RVE prepared at sigma = -p I before the analysis (0: as built)
  unsigned int initial_pressure_stages; ///< RVE: stages of that preparation
  double initial_pressure_tolerance;    ///< RVE: relative tolerance of its normal stresses
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
  /**
   * @throws std::runtime_error naming the entry if RVEs cannot run in time (explicit
   * dynamics, slow loading) so; @p analysis names the setting that asks for it.
   */
  void check_for_dynamics(const std::string& analysis) const;
  /// The P-wave speed the stable steps are estimated with [m/s]: sqrt((lambda
  /// + 2 mu)/rho), or sqrt(Stability modulus / rho) for RVEs; the
  /// Material::wave_speed() of the material built from these entries.
  double wave_speed() const;
};

/**
 * subsection Finite elements: the quadrature of the Q1 elements
 * (one_point_elements.h). One point per element means one RVE per element.
 */
struct FiniteElements
{
  bool one_point; ///< one point per element (uniform gradient) instead of 2x2 (2x2x2) Gauss
  enum class Hourglass
  {
    none,      ///< no control: the zero-energy modes stay (testing)
    stiffness, ///< Flanagan-Belytschko stiffness form (quasi-static and dynamic)
    viscous    ///< Flanagan-Belytschko viscous form (dynamic)
  } hourglass;
  double hourglass_coefficient; ///< epsilon of one_point_elements.h, in (0, 1]
  bool corotational;            ///< corotational update (corotational_material.h) instead of total Lagrangian
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/**
 * subsection Nonlocal: the staggered nonlocal operator of physics.md 1.5
 * ([LSYF] 2.3.3; nonlocal/nonlocal_material.h). The strain increment that
 * drives each IP's material is the bell-weighted average of the increments
 * of the IPs within 'Interaction radius' of it, so that a shear band cannot
 * narrow below a width set by the radius instead of by the mesh.
 */
struct Nonlocal
{
  double radius; ///< interaction radius R (m, reference configuration); 0: local
  /// The weight function of support R (nonlocal_operator.h): Wendland's positive-definite C2
  /// function, or [LSYF]'s bell, whose average turns indefinite once R exceeds ~1.3-1.9 IP spacings.
  enum class Weight
  {
    wendland,
    bell
  } weight;
  /// The neighbours' increments at n+alpha: (1 - alpha) x their last committed
  /// increment + alpha x their current one; the point's own is always current.
  double alpha;
  /// What the average drives (nonlocal_material.h): the whole stress ([LSYF]), or only the
  /// material's departure from a local elastic law C_e (Bazant & Lin 1988).
  enum class Formulation
  {
    total_strain,
    local_elastic
  } formulation;
  double elastic_modulus; ///< C_e's Young's modulus (Pa; 2D: N/m), local_elastic only
  double poisson_ratio;   ///< C_e's Poisson ratio (2D: plane strain), local_elastic only
  /// Whose volume change drives the material: the averaged one ([LSYF]) or the point's own.
  enum class Volume
  {
    averaged,
    own
  } volume_change;
  bool active() const { return radius > 0.0; }
  /// C_e's Lame constants from its E and nu (2D: plane strain); 0 for total_strain.
  double elastic_lambda() const;
  double elastic_mu() const;
  /// C_e's P-wave modulus lambda + 2 mu (0 for total_strain).
  double elastic_p_wave_modulus() const { return elastic_lambda() + 2.0 * elastic_mu(); }
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/**
 * subsection Imperfection: RVEs built from another packing, e.g. the RVE's
 * packing with particles removed, which seed a shear band ([LSYF] §3.2,
 * problem 3: 25 particles removed from one RVE): the one IP nearest a
 * point, or every IP in a box around it (a weak region the same on every
 * mesh).
 */
struct Imperfection
{
  std::string packing;           ///< packing prefix (absolute); empty: none
  std::array<double, 3> point{}; ///< reference position [m]: the nearest IP, or the box's centre
  std::array<double, 3> size{};  ///< the box's edge lengths [m]; all 0: the IP nearest @p point
  bool active() const { return !packing.empty(); }
  bool box() const { return size[0] > 0.0; }
  static void declare_parameters(dealii::ParameterHandler& prm);
  /// @param base the parameter file's folder (relative prefixes); @param dim the number of coordinates
  void parse_parameters(dealii::ParameterHandler& prm, const std::string& base, unsigned int dim);
};

/// subsection Dynamic relaxation: physics.md (M3)-(M9).
struct DynamicRelaxation
{
  /// How omega of (M6) is estimated at each iteration.
  enum class FrequencyEstimate
  {
    secant,     ///< (M6): U^T f_int / U^T M U over the free dofs ([LBS])
    incremental ///< the change over the last iteration: dU^T df_int / dU^T M dU over all dofs
  };
  FrequencyEstimate frequency_estimate;
  /// The free dofs' first iterate of a load step.
  enum class Predictor
  {
    none,       ///< where the last step ended ([LBS])
    extrapolate ///< plus the last step's increment, scaled to this one
  };
  Predictor predictor;
  /// The free dofs' first iterate of a load step that is not extrapolated.
  enum class BoundaryExtension
  {
    none,   ///< only the prescribed dofs move ([LBS])
    elastic ///< the elastic extension of their increment (elastic_extension.h)
  };
  BoundaryExtension boundary_extension;
  double extension_poisson_ratio; ///< nu of the elastic extension, in [0, 0.5)
  double damping_ratio, safety_factor, kinetic_tolerance;
  unsigned int max_iterations, min_iterations;
  unsigned int ramp_iterations; ///< the step's load grows over this many iterations (0: at once)
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/**
 * subsection Dynamics: the analysis. Quasi-static by slow loading (explicit
 * dynamics at a low strain rate with a numerical mass and local damping:
 * the limit DEM calls quasi-static) or by relaxed steps (dynamic relaxation
 * of every load step, [LBS]/[LSYF]), or explicit dynamics (central
 * differences, central_difference.h).
 */
struct Dynamics
{
  /// How a quasi-static analysis reaches each load step.
  enum class Scheme
  {
    relaxed_steps, ///< dynamic relaxation to rest at every step ([LBS] (M3)-(M9))
    slow_loading   ///< central differences at 'Strain rate', mass and damping numerical
  };
  bool dynamic;          ///< explicit dynamics instead of a quasi-static analysis
  Scheme scheme;         ///< quasi-static: 'Quasi-static scheme', 'auto' resolved by resolve_scheme()
  bool scheme_auto;      ///< 'Quasi-static scheme' = auto
  double strain_rate;    ///< slow loading: nominal strain rate of the fastest load step [1/time]
  double local_damping;  ///< slow loading: Cundall's local damping of the nodal forces, in [0, 1)
  double time_step;      ///< fixed step [time]; 0: safety_factor x the critical step
  double safety_factor;  ///< of the critical step, in (0, 1]
  double rayleigh_alpha; ///< mass-proportional damping C = alpha M + beta K [1/time]
  double rayleigh_beta;  ///< stiffness-proportional damping [time]
  double mass_scaling;   ///< density factor >= 1 of the mass matrix (waves slower by its square root)
  bool slow_loading() const { return !dynamic && scheme == Scheme::slow_loading; }
  bool relaxed_steps() const { return !dynamic && scheme == Scheme::relaxed_steps; }
  /// Central differences advance the state (explicit dynamics or slow loading).
  bool central_differences() const { return dynamic || scheme == Scheme::slow_loading; }
  /// The factor of the density in the mass matrix: 'Mass scaling' in dynamics, 1 otherwise
  /// (slow loading scales its numerical mass itself, central_difference_analysis.h).
  double mass_factor() const { return dynamic ? mass_scaling : 1.0; }
  /// 'auto': slow loading for RVE materials (path-dependent), relaxed steps otherwise.
  void resolve_scheme(bool rve_material);
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/// subsection Loading: boundary conditions and load steps.
struct Loading
{
  enum class Boundary
  {
    biaxial,   ///< 2D compression test (load_case.h: CompressionLoadCase)
    triaxial,  ///< 3D compression test (the same load case in 3D)
    affine,
    conditions ///< subsections Boundary condition N (conditions_load_case.h)
  } boundary;                 ///< the load case (load_case.h)
  double end_time;            ///< conditions: t of the functions at the last load step
  double pressure;            ///< biaxial/triaxial: confining follower pressure [force/length in 2D, force/area in 3D]
  unsigned int isotropic_steps; ///< stage 1: pressure on the sides and the top
  double axial_strain;        ///< stage 2: compressive strain of h_ic
  /// affine: F row-major at the last step, dim x dim values ({F11, F12, F21, F22} in 2D)
  std::array<double, 9> affine_F;
  unsigned int steps;         ///< biaxial/triaxial stage 2 / affine: load steps
  static void declare_parameters(dealii::ParameterHandler& prm);
  /// @param dim the Geometry's dimension (the size of 'Affine F', the name of the test).
  void parse_parameters(dealii::ParameterHandler& prm, unsigned int dim);
};

/**
 * subsection Boundary condition N (N = 1 .. max_count): one condition of
 * 'Boundary = conditions' on one boundary, with functions of the reference
 * position (x, y, z) and the pseudo-time t (deal.II FunctionParser).
 */
struct BoundaryCondition
{
  static constexpr unsigned int max_count = 8;
  enum class Type
  {
    fixed,        ///< listed components zero
    displacement, ///< listed components u_c = f_c(X, t)
    velocity,     ///< listed components u_c = integral of f_c(X, s) ds from 0 to t
    traction,     ///< dead load: nominal traction T(X, t) (dim functions) on the reference face
    pressure      ///< follower pressure p(t) normal to the current face (one function)
  } type;
  unsigned int number = 0;            ///< N of its subsection 'Boundary condition N' (messages)
  std::string boundary_text;          ///< as written (messages)
  unsigned int boundary_id;           ///< fe2dem's id (load_case.h BoxFace, 2 dim: other)
  std::vector<unsigned int> components; ///< fixed/displacement/velocity: constrained components
  std::string function;               ///< ';'-separated expressions
  /// Expressions 'Function' must hold: 0 (fixed), dim (traction), 1 (pressure), else one per component.
  unsigned int n_functions(unsigned int dim) const
  {
    return type == Type::fixed ? 0 : type == Type::traction ? dim : type == Type::pressure ? 1 : components.size();
  }
  static void declare_parameters(dealii::ParameterHandler& prm);
  /// All used subsections, in order. @param dim of the Geometry. @throws std::runtime_error naming the subsection.
  static std::vector<BoundaryCondition> parse_all(dealii::ParameterHandler& prm, unsigned int dim);
};

/// subsection Particle dumps: particle pictures of chosen IPs (coupler/particle_dump.h).
struct ParticleDumps
{
  std::vector<unsigned int> points; ///< IP indices as in history.h5
  unsigned int every;               ///< every this many load steps (and the last)
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/// subsection Parallel: placement of the RVEs on the ranks (never changes results).
struct Parallel
{
  bool rebalance; ///< re-place RVEs by measured cost after every converged load step
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/// subsection Checkpoint: periodic checkpoints for --resume (checkpoint_file.h).
struct Checkpointing
{
  unsigned int every; ///< load steps between checkpoints (0: only on signals and stops)
  unsigned int keep;  ///< newest checkpoints kept
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/// subsection Faults: what a failed RVE solve does to the run.
struct Faults
{
  bool cut_step;           ///< cut the load step and retry (else stop with a checkpoint)
  unsigned int max_cuts;   ///< halvings of one load step before stopping
  int inject_ip = -1;      ///< test only: IP whose RVE gets a fault of kind inject_kind ...
  unsigned int inject_step = 0; ///< ... at the first attempt of this load step
  RveFault inject_kind = RveFault::step_budget;
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

struct Parameters
{
  std::string output_directory;
  Geometry geometry;
  MaterialParameters material;
  FiniteElements elements;
  Nonlocal nonlocal;
  Imperfection imperfection;
  DynamicRelaxation relaxation;
  Dynamics dynamics;
  Loading loading;
  std::vector<BoundaryCondition> conditions; ///< 'Boundary = conditions' only
  ParticleDumps particle_dumps;
  Checkpointing checkpoint;
  Parallel parallel;
  Faults faults;
  /// Every entry that defines the results (checked on --resume), as
  /// 'subsection/entry = value' lines: all but Output directory and the
  /// subsections Checkpoint, Faults, Parallel and Particle dumps; with RVEs
  /// also fingerprints of the template and packing files.
  std::string identity;
  std::string file; ///< the parameter file
  RveParameters rve; ///< subsection RVE (Material type = RVE)
  static void declare_parameters(dealii::ParameterHandler& prm);
  /// Reads @p file into every subsection and checks the subsections against each other.
  void parse(dealii::ParameterHandler& prm, const std::string& file);

private:
  /// With RVEs: checks the template and packing files (and the imperfection's) and adds their
  /// fingerprints to #identity.
  void add_rve_files(const std::string& file);
};
} // namespace fe2dem::macro
