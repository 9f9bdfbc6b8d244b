#include "report/paper_tables.hpp"

#include "report/reference_table.hpp"

#include <fmt/format.h>
#include "core/json.hpp"

#include <cmath>
#include <fstream>
#include <optional>

namespace mrsph::verification {

namespace {


std::optional<Json> summary_of(const std::filesystem::path& run_dir, const std::string& suite) {
  std::ifstream in(run_dir / suite / "summary.json");
  if (!in) return std::nullopt;
  return Json::parse(in);
}

const Json* run_named(const Json& summary, const std::string& name) {
  for (const Json& r : summary.at("runs"))
    if (r.value("case", "") == name) return &r;
  return nullptr;
}

std::string value(const Json* run, const char* metric, const char* format = "{:.3f}") {
  if (!run || !run->at("metrics").contains(metric) || !run->at("metrics")[metric].is_number()) return "-";
  return fmt::format(fmt::runtime(format), run->at("metrics")[metric].get<double>());
}

std::string wall(const Json* run) {
  if (!run || !run->at("cost").contains("wall_s")) return "-";
  return fmt::format("{:.1f}", run->at("cost")["wall_s"].get<double>());
}

// Table 2: FSI2 cases I-V beside the paper's, Turek & Hron and the paper's code run here.
std::string table_2(const std::filesystem::path& run_dir, const Json& refs) {
  std::string md = "## Table 2: FSI2, cases I-IV (A_y/D, St = f D/U0, time to t = 200)\n\n";
  if (const auto th = summary_of(run_dir, "turek-hron")) {
    const int threads = th->at("machine").value("threads", 0);
    if (th->value("mode", "") == "quick")
      md += "Quick mode: case III only, to t = 70; the amplitude is measured over t = 40-70 while it still grows.\n\n";
    md += fmt::format("| case | dp_F/dp_S | dp_S | steps | paper A_y/D | ours A_y/D | paper St | ours St | paper CPU s (Xeon L5520, TBB) "
                      "| ours wall s ({} thread{}) |\n|---|---|---|---|---|---|---|---|---|---|\n", threads, threads == 1 ? "" : "s");
    for (const char* name : {"I", "II", "III", "IV", "V"}) {
      const Json* r = run_named(*th, name);
      if (!r) continue;
      const Json& c = r->at("config");
      const Json paper = refs["paper_table_2"]["cases"].value(name, Json::object());
      md += fmt::format("| {} | {} | bh/{} | {} | {} | {} | {} | {} | {} | {} |\n", name, c.value("ratio", 0), c.value("resolution", 0),
                        c.value("schedule", "").find("single") != std::string::npos ? "single" : "multiple",
                        paper.contains("amplitude_y") ? fmt::format("{:.2f}", paper["amplitude_y"].get<double>()) : "-",
                        value(r, "amplitude_y"),
                        paper.contains("strouhal") ? fmt::format("{:.3f}", paper["strouhal"].get<double>()) : "-",
                        value(r, "strouhal"),
                        paper.contains("cpu_s") ? fmt::format("{:.1f}", paper["cpu_s"].get<double>()) : "-", wall(r));
    }
    md += fmt::format("\nTurek & Hron (2006): A_y/D = {}, St = {}. The paper's code run here (case III, 2 threads): "
                      "A_y/D = {}, St = {}, about {} s.\n",
                      refs["turek_hron_2006"]["amplitude_y"].dump(), refs["turek_hron_2006"]["strouhal"].dump(),
                      refs["paper_code_here"]["amplitude_y"].dump(), refs["paper_code_here"]["strouhal"].dump(),
                      refs["paper_code_here"]["wall_s"].dump());
    if (th->contains("speedups"))
      md += fmt::format("Speed-ups: III vs I {} (paper {:.1f}), III vs IV {} (paper {:.1f}).\n\n",
                        (*th)["speedups"].contains("III_vs_I") ? fmt::format("{:.1f}", (*th)["speedups"]["III_vs_I"].get<double>()) : "-",
                        (*th)["speedups"]["paper_III_vs_I"].get<double>(),
                        (*th)["speedups"].contains("III_vs_IV") ? fmt::format("{:.1f}", (*th)["speedups"]["III_vs_IV"].get<double>()) : "-",
                        (*th)["speedups"]["paper_III_vs_IV"].get<double>());
  } else {
    md += "Not in this run directory: run `verify --suite turek-hron`.\n\n";
  }

  return md;
}

// Table 3: case III's convergence beside the paper's.
std::string table_3(const std::filesystem::path& run_dir, const Json& refs) {
  std::string md = "## Table 3: FSI2 convergence of case III\n\n";
  const Json& t3 = refs["paper_table_3"];
  if (const auto cv = summary_of(run_dir, "convergence")) {
    md += "| bh/dp_S | paper A_y/D | ours A_y/D | paper St | ours St |\n|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < t3["resolution"].size(); ++k) {
      const int res = t3["resolution"][k];
      const Json* r = run_named(*cv, fmt::format("FSI2 bh/dp_S={}", res));
      md += fmt::format("| {} | {:.3f} | {} | {:.3f} | {} |\n", res, t3["amplitude_y"][k].get<double>(), value(r, "amplitude_y"),
                        t3["strouhal"][k].get<double>(), value(r, "strouhal"));
    }
    md += "\n";
  } else {
    md += "Not in this run directory: run `verify --suite convergence`.\n\n";
  }

  return md;
}

// Table 5: the gate's cases beside the paper's CPU times, the experiment and the paper's code run here.
std::string table_5(const std::filesystem::path& run_dir, const std::filesystem::path& project_dir) {
  std::string md = "## Table 5: elastic gate, time to t = 0.4 s\n\n";
  if (const auto an = summary_of(run_dir, "antoci")) {
    const int threads = an->at("machine").value("threads", 0);
    const Json paper = read_project_reference(project_dir, "antoci_gate.json")["paper_cpu_s"];
    md += fmt::format("| case | paper CPU s | ours wall s ({} thread{}) | RMS x vs experiment [mm] | peak x [mm] at [s] |\n"
                      "|---|---|---|---|---|\n", threads, threads == 1 ? "" : "s");
    for (const char* name : {"I", "II", "III", "IV", "III-B0"}) {
      const Json* r = run_named(*an, name);
      if (!r) continue;
      md += fmt::format("| {} | {} | {} | {} | {} at {} |\n", name,
                        paper.contains(name) ? fmt::format("{:.2f}", paper[name].get<double>()) : "-", wall(r),
                        value(r, "rms_error_x_mm", "{:.2f}"), value(r, "peak_x_mm", "{:.1f}"), value(r, "peak_time_s", "{:.3f}"));
    }
    if (an->contains("speedup_III_vs_IV"))
      md += fmt::format("\nSpeed-up of III over IV: {:.1f} (paper {:.1f}).\n",
                        (*an)["speedup_III_vs_IV"]["ours"].get<double>(), (*an)["speedup_III_vs_IV"]["paper"].get<double>());
    if (an->contains("experiment_peak")) {
      const Json& e = (*an)["experiment_peak"];
      md += fmt::format("Experiment: peak {:.1f} mm at {:.3f} s (first sample subtracted). ", e["x_mm"].get<double>(),
                        e["time_s"].get<double>());
    }
    if (an->contains("paper_code_here")) {
      const Json& c = (*an)["paper_code_here"];
      md += fmt::format("The paper's code run here: {:.1f} mm at {:.3f} s, RMS {:.1f} mm, {} s.", c["peak_x_mm"].get<double>(),
                        c["peak_time_s"].get<double>(), c["rms_error_x_mm"].get<double>(), c["wall_s"].get<std::string>());
    }
    md += "\n";
  } else {
    md += "Not in this run directory: run `verify --suite antoci`.\n";
  }
  return md;
}

}  // namespace

std::string paper_tables(const std::filesystem::path& run_dir, const std::filesystem::path& project_dir) {
  const Json refs = read_project_reference(project_dir, "turek_hron_fsi2.json");
  return "# The paper's tables beside this run (" + run_dir.string() + ")\n\n" + table_2(run_dir, refs) +
         table_3(run_dir, refs) + table_5(run_dir, project_dir);
}

}  // namespace mrsph::verification
