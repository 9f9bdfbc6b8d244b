// Checkpoints: everything a run needs to continue exactly where it stopped. Taken at the end of an
// advection step (after the pair lists were rebuilt), they hold the scene after overrides, the
// clock, the runner's output state and every particle array the next steps read (including the
// Riemann dissipation applied one acoustic step late and the solid's averaged kinematics). On
// restart the pair lists are rebuilt from the restored positions without reordering, so a
// restarted run with the same thread count is bitwise equal to an uninterrupted one.
// Files are written atomically (temporary file, then rename).
#pragma once

#include "scene/scene_node.hpp"
#include "run/runner.hpp"
#include "simulation/simulation.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mrsph {

// In-memory form, so the runner can keep the last good state and write it on demand.
std::string serialise_checkpoint(const Json& scene_document, const std::string& scene_file, const Simulation& sim,
                                 const RunnerState& runner);

// A checkpoint kept in memory without the observers' series, which only grow: the bytes before and
// after them and each series' row count at the time it was kept. Keeping one every few steps then
// costs the particle state, not the run's whole history, whose copies grew with the run's length
// (FSI2 case III to t = 200: about 1 % of the run, reports/performance.md section 24).
struct KeptCheckpoint {
  std::string before_series, after_series;
  std::vector<std::size_t> series_rows;
};
// Keeps the checkpoint of this moment in `kept`, reusing its buffers.
void keep_checkpoint(const Json& scene_document, const std::string& scene_file, const Simulation& sim,
                     const RunnerState& runner, KeptCheckpoint& kept);
// The checkpoint as serialise_checkpoint gave it when it was kept, from the series as they are now
// (the same series, grown since). Throws std::logic_error if they are not.
std::string assemble_checkpoint(const KeptCheckpoint& kept, const std::vector<ObserverSeries>& series);
void write_checkpoint(const std::filesystem::path& path, const std::string& bytes);

struct CheckpointHeader {
  Json scene_document;
  std::string scene_file;
  Real time = 0.0;
};
// Reads the scene stored in a checkpoint (to rebuild the simulation before restoring it).
CheckpointHeader read_checkpoint_header(const std::filesystem::path& path);
// Restores particle state, clock and runner state into a simulation built from that scene.
// Throws std::runtime_error naming the file and what does not fit.
void restore_checkpoint(const std::filesystem::path& path, Simulation& sim, RunnerState& runner);

}  // namespace mrsph
