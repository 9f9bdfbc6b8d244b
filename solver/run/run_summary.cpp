#include "run/run_summary.hpp"

#include <thread>

namespace mrsph {

nlohmann::ordered_json particle_counts(const Simulation& sim) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (sim.has_fluid()) j[sim.fluid().name] = sim.fluid().particles.size();
  for (const auto& w : sim.walls()) j[w.name] = w.particles.size();
  for (const auto& s : sim.solids()) j[s.name] = s.particles.size();
  return j;
}

nlohmann::ordered_json step_counts(const StepCounters& steps) {
  return {{"advection", steps.advection}, {"acoustic", steps.acoustic}, {"solid", steps.solid}};
}

nlohmann::ordered_json divergence_json(const DivergenceInfo& info) {
  return {{"time", info.time}, {"step", info.step}, {"body", info.body}, {"particle", info.particle}, {"reason", info.reason}};
}

nlohmann::ordered_json compressibility_json(const CompressibilityRecord& record) {
  auto extreme = [](const FluidExtreme& e) {
    return nlohmann::ordered_json{{"value", e.value}, {"time", e.time}, {"position", {e.position.x(), e.position.y()}}};
  };
  return {{"max_density_deviation", extreme(record.density_deviation)}, {"max_mach", extreme(record.mach)}};
}

// Per open boundary: the mass that crossed its plane into the domain and the particles made and
// removed; with the domain's mass now, the mass balance can be checked from the summary alone.
nlohmann::ordered_json open_boundaries_json(const Simulation& sim) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const OpenBoundary& b : sim.open_boundaries)
    list.push_back({{"name", b.name}, {"mass_into_domain", b.ledger.mass_into_domain},
                    {"particles_created", b.ledger.created}, {"particles_deleted", b.ledger.deleted}});
  return {{"domain_mass", domain_mass(sim.fluid().particles)}, {"boundaries", list}};
}

nlohmann::ordered_json run_summary_json(const LoadedScene& scene, const RunResult& result, int threads) {
  nlohmann::ordered_json j;
  j["scene"] = scene.name;
  j["file"] = scene.file;
  j["completed"] = result.completed;
  j["interrupted"] = result.interrupted;
  j["diverged"] = result.divergence.has_value();
  if (!result.checkpoint_written.empty()) j["checkpoint"] = result.checkpoint_written.string();
  if (!result.last_good_written.empty()) j["last_good_state"] = result.last_good_written.string();
  if (result.divergence) j["divergence"] = divergence_json(*result.divergence);
  j["end_time"] = scene.run.end_time;
  j["time_reached"] = result.end_time_reached;
  j["schedule"] = scene.schedule->name();
  j["machine"] = {{"threads", threads}, {"hardware_concurrency", std::thread::hardware_concurrency()}};
  j["cost"] = {{"wall_s", result.wall_s}, {"cpu_s", result.cpu_s},
               {"particles", particle_counts(*scene.simulation)}, {"steps", step_counts(result.steps)}};
  if (scene.simulation->has_fluid()) j["compressibility"] = compressibility_json(result.compressibility);
  if (!scene.simulation->open_boundaries.empty()) j["open_boundaries"] = open_boundaries_json(*scene.simulation);
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (const auto& s : result.series) files.push_back("observers/" + s.name + ".csv");
  j["observers"] = files;
  j["config"] = scene.document;
  nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
  for (const auto& [name, value] : scene.parameters) parameters[name] = value;
  j["parameters"] = parameters;
  return j;
}

}  // namespace mrsph
