/**
 * @file checkpoint_file.h
 * Checkpoints of `fe2dem` runs: one HDF5 file per checkpoint,
 * OUTPUT/checkpoints/checkpoint-NNNNNN.h5 (NNNNNN = last converged load
 * step), written under a temporary name and renamed only when complete, so
 * a file with the final name is always whole.
 *
 * Layout: attributes format, step, stage, step_in_stage,
 * loading_start_u_top, loading_start_height (SpecimenMeasures::Reference),
 * wall_seconds; datasets /load_case_state (LoadCase::state(), may be
 * empty), /displacement and /step_increment (the last load
 * step's change, for 'Predictor = extrapolate') [n_dofs], /ip_state [n_ip][n],
 * /summary_rows, /energy_rows and /parameters (strings), /energy_state
 * (EnergyBalance::pack()), /dynamics_state (t, v, a, f_int; empty when
 * quasi-static), /rve/NNNNNN (committed state of
 * RVE k as bytes, a LIGGGHTS restart image) and /history/ (a copy of
 * history.h5 up to this step).
 */
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace fe2dem::macro
{
class HistoryWriter;

/// The macro side of a checkpoint (identical on all ranks).
struct CheckpointData
{
  int step = 0, stage = 1, step_in_stage = 0; ///< last converged load step
  std::vector<double> load_case_state;        ///< LoadCase::state()
  double loading_start_u_top = 0.0;           ///< the top face when the loading stage began
  double loading_start_height = 0.0;          ///< (SpecimenMeasures::Reference)
  double wall_seconds = 0.0;                  ///< wall time of the run so far
  std::vector<double> displacement;           ///< nodal displacements, dof order
  std::vector<double> step_increment;         ///< their change over the last load step, dof order
  std::size_t ip_state_width = 0;
  std::vector<double> ip_state;               ///< per IP, ip_state_width values
  std::string summary_rows;                   ///< summary.csv rows so far (no header)
  std::string energy_rows;                    ///< energy.csv rows so far (no header)
  std::vector<double> energy_state;           ///< EnergyBalance::pack()
  std::vector<double> dynamics_state;         ///< explicit dynamics: t, then v, a, f_int (dof order); else empty
  std::string parameters;                     ///< the run's parameters (see checked_parameters)
};

/**
 * Writes checkpoint @p file (rank 0 only): @p data, the committed RVE
 * states @p rve_states (may be empty) and a copy of @p history (may be null).
 * @throws std::runtime_error naming the file if it cannot be written.
 */
void write_checkpoint(const std::string& file, const CheckpointData& data,
                      const std::vector<std::vector<char>>& rve_states, const HistoryWriter* history);

/// Reads the macro side. @throws std::runtime_error naming the file.
CheckpointData read_checkpoint(const std::string& file);

/**
 * Why checkpoint @p file cannot be trusted, or "" if it can: its bytes must
 * match the fingerprint write_checkpoint() put beside it (FILE.fnv, written
 * before the checkpoint got its final name), so that a truncated or altered
 * file is detected before anything is read from it.
 */
std::string damage_of(const std::string& file);

/// history.h5 recreated at @p history_file from the copy in checkpoint @p file, to append to.
std::unique_ptr<HistoryWriter> restore_history(const std::string& file, const std::string& history_file);

/// The committed state of RVE @p k in checkpoint @p file.
std::vector<char> read_rve_state(const std::string& file, std::size_t k);

/// Path of checkpoint number @p step in @p directory.
std::string checkpoint_path(const std::string& directory, int step);

/// Complete checkpoints in @p directory, oldest first (temporary files ignored).
std::vector<std::string> list_checkpoints(const std::string& directory);

/// Deletes all but the newest @p keep complete checkpoints (and their fingerprints) in @p directory.
void prune_checkpoints(const std::string& directory, unsigned int keep);
} // namespace fe2dem::macro
