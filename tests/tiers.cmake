# Test tiers (issue 36). Every test carries one label for what it exercises:
#
#   unit       pure parts, no LIGGGHTS instance (homogenisation, the rate
#              control model, frame geometry, solver parts, layer rules)
#   rve        fix rve/servo, the coupler and fe2dem-rve through real LIGGGHTS
#   macro      fe2dem runs and the checks that read them
#   bad_input  bad input: each must stop with a message naming the file,
#              entry or keyword and the value
#   restart    kill/resume, signals, faults, damaged checkpoints, a full
#              disk, the output lock, SLURM requeue
#
# and the verification runs of tens of seconds to minutes carry `long` as
# well. scripts/run-tests.sh runs `ctest -LE long` (about 8 minutes with the
# build on the 2-core machine); `ctest -L long` runs the rest (about 25
# minutes; tests/README.md lists what is there and why).
#
# A test that needs the output of a long run is long itself: ctest starts
# the fixture setup of every selected test whatever its labels, so a check
# left in the default tier would pull its long run back in.

set(FE2DEM_UNIT_TESTS
  homogenisation_hand_computed rve_continuous_rate_control_model
  frame_3d_face_triangulation frame_3d_corner_choice frame_servo_controller frame_motion_paths frame_progress_watch frame_membrane_push_and_balance
  layers_solver_without_liggghts layers_solver_parts_without_liggghts layers_common_without_liggghts layers_rve_driver_without_liggghts docs_parameters_up_to_date
  macro_one_point_element_modes macro_dynamic_relaxation_estimates
  macro_elastic_extension macro_nonlocal_operator benchmark_band_width_known_bands)

# Runs of more than ~12 s alone on one core, each with the reason it is not
# in the default tier beside a cheaper sibling that keeps the guarantee
# there (tests/README.md, "Test tiers").
set(FE2DEM_LONG_RUNS
  # 3D one-element multiscale against fe2dem-rve (minutes)
  macro_3d_one_element_triaxial macro_3d_one_element_triaxial_rve
  macro_3d_one_element_shear macro_3d_one_element_shear_rve
  macro_3d_one_element_triaxial_to_2_percent
  # 3D multiscale and pools on 1 and 2 ranks (2D siblings stay)
  macro_3d_rve_np1 macro_3d_rve_np2 coupler_3d_pool_np1 coupler_3d_pool_np2
  restart_3d_rve_kill_np2_resume_np1
  # [LSYF] anchors and the continuous references of issue 35
  rve_3d_lsyf_moduli rve_continuous_shear_reference rve_continuous_triaxial_reference
  rve_continuous_triaxial_reference_affine
  rve_continuous_proportional_0.25 rve_continuous_proportional_0.125
  rve_continuous_integral_0.125 rve_continuous_hold_rows
  # the held diagnostics of the non-default 'Solve drive' = continuous on
  # small_3d (the lsyf_1000 continuous drive against YADE stays)
  rve_continuous_small_3d_keep
  rve_continuous_ensemble_0.25 rve_continuous_ensemble_0.125 rve_continuous_ensemble_0.0625
  rve_continuous_ensemble_0.03125
  # RVEs prepared at a pressure, dynamic (the unprepared dynamic runs stay)
  macro_prepared_rve_holds_its_pressure macro_dynamic_rve_prepared_np1
  macro_dynamic_rve_prepared_np2 restart_dynamic_rve_prepared_kill_np2_resume_np1
  macro_dynamic_rve_triaxial_slow macro_dynamic_rve_shear_fast macro_dynamic_rve_shear_slow
  # the shipped 2x4 example to 1.5 % against the strict [LBS] run (32 RVEs, 2 ranks)
  macro_example_biaxial_2x4_vs_strict
  # the shipped examples not run elsewhere, as shipped (minutes each)
  macro_example_biaxial_1x1_as_shipped rve_example_triaxial_3d_as_shipped
  # the 3D simple-shear example against its fe2dem-rve reference (55 s; the
  # 3D slow-loading column with RVEs stays)
  rve_example_simple_shear_3d_reference
  # [LSYF] problem 2 at full size: the linear wave column and its M, the
  # 0.1 mm column and its RVE's sigma(eps) to 1 % (minutes each)
  macro_lsyf_constrained_modulus macro_lsyf_wave_column_1um
  macro_lsyf_constrained_modulus_1_percent macro_lsyf_wave_column_0.1mm
  # slow loading against the continuous reference (the column stays)
  macro_slow_loading_triaxial_0.25 macro_slow_loading_triaxial_0.125
  # waves and beams of many steps (the 2D energy checks stay)
  macro_dynamics_wave_column_3d_one_point macro_dynamics_wave_column_2d
  macro_one_point_beam
  # 1, 4 and 8 ranks (1 vs 2 ranks stays, in 2D and with dynamic RVEs)
  macro_ranks_1_4_8_bitwise
  # 3D fe2dem-rve paths and membranes (the 3D table path and lattices stay)
  rve_free_shear_3d rve_example_triaxial_3d rve_3d_random_packing
  rve_membrane_yes rve_membrane_no
  coupler_3d_increment coupler_3d_rollback
  rve_never_relaxed_names_the_fix rve_never_relaxed_continuous_gets_past
  rve_timed_hold_is_equilibrium
  macro_corotational_vs_total_lagrangian_3d macro_ramp_elastic_block_3d
  # the nonlocal patch test on a fine mesh (the coarse 2D and 3D ones stay);
  # nonlocal RVEs in 3D explicit dynamics (the 2D quasi-static ones stay)
  macro_nonlocal_fine_patch_test_2d macro_nonlocal_dynamic_3d_np1 macro_nonlocal_dynamic_3d_np2
  restart_nonlocal_dynamic_3d_kill_np2_resume_np1
  # 'Volume change' = own with RVEs in 2D (the unit test and the 3D patch test stay)
  macro_nonlocal_own_volume_2d_np1 macro_nonlocal_own_volume_2d_np2
  restart_nonlocal_own_volume_2d_kill_np2_resume_np1
  # restart variants of one guarantee (kill/resume, SIGTERM stay)
  shm_images_removed restart_dynamics_kill_np1_resume_np2
  restart_damaged_checkpoint_truncated restart_damaged_checkpoint_corrupted
  restart_sigint_np1 restart_sigusr1_np2
  fault_dynamic_rve_stop_and_resume fault_dynamic_rve_liggghts_error_np2
  fault_liggghts_error_stop_and_resume
  macro_incremental_estimate_1_vs_2_ranks)

get_property(fe2dem_all_tests DIRECTORY PROPERTY TESTS)
foreach(t IN LISTS FE2DEM_LONG_RUNS)
  if(NOT t IN_LIST fe2dem_all_tests)
    message(FATAL_ERROR "tests/tiers.cmake: FE2DEM_LONG_RUNS names '${t}', which is not a test; remove or rename it")
  endif()
endforeach()

# Fixtures set up by long tests, to a fixed point: long runs make long checks.
set(long_tests ${FE2DEM_LONG_RUNS})
set(changed TRUE)
while(changed)
  set(changed FALSE)
  set(long_fixtures "")
  foreach(t IN LISTS long_tests)
    get_test_property(${t} FIXTURES_SETUP setup)
    if(setup)
      list(APPEND long_fixtures ${setup})
    endif()
  endforeach()
  foreach(t IN LISTS fe2dem_all_tests)
    if(t IN_LIST long_tests)
      continue()
    endif()
    get_test_property(${t} FIXTURES_REQUIRED required)
    foreach(f IN LISTS required)
      if(f IN_LIST long_fixtures)
        list(APPEND long_tests ${t})
        set(changed TRUE)
        break()
      endif()
    endforeach()
  endforeach()
endwhile()

foreach(t IN LISTS fe2dem_all_tests)
  if(t IN_LIST FE2DEM_UNIT_TESTS)
    set(tier unit)
  elseif(t MATCHES "^bad_")
    set(tier bad_input)
  elseif(t MATCHES "^(restart|fault|io_error|shm|second_writer|slurm)_")
    set(tier restart)
  elseif(t MATCHES "^(macro|install)_")
    set(tier macro)
  elseif(t MATCHES "^(rve|coupler|contact_pair|frame)_")
    set(tier rve)
  else()
    message(FATAL_ERROR "tests/tiers.cmake: test '${t}' matches no tier; name it with a tier's prefix or list it in FE2DEM_UNIT_TESTS")
  endif()
  if(t IN_LIST long_tests)
    set_tests_properties(${t} PROPERTIES LABELS "${tier};long")
  else()
    set_tests_properties(${t} PROPERTIES LABELS "${tier}")
  endif()
endforeach()
