#include "report/markdown_report.hpp"

#include "core/json.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <thread>

namespace mrsph::verification {

namespace {


std::string number(const Json& v) {
  if (v.is_null()) return "-";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_number()) return fmt::format("{:.4g}", v.get<double>());
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

std::string escape(std::string s) {
  for (std::size_t k = 0; (k = s.find('|', k)) != std::string::npos; k += 2) s.replace(k, 1, "\\|");
  return s;
}

void suite_section(std::string& md, const std::string& name, const Json& s) {
  md += fmt::format("## {} ({}) - {}\n\n", name, s.value("mode", "?"), s.value("passed", false) ? "PASSED" : "**FAILED**");
  md += "| check | value | reference | tolerance | verdict | source |\n|---|---|---|---|---|---|\n";
  for (const Json& c : s.at("checks")) {
    std::string reference = number(c.value("reference", Json()));
    std::string tolerance = number(c.value("tolerance", Json()));
    const std::string kind = c.value("kind", "");
    if (kind == "range") { reference = fmt::format("[{}, {}]", number(c["lower"]), number(c["upper"])); tolerance = "range"; }
    if (kind == "at_most") { reference = "<= " + number(c["reference"]); tolerance = "-"; }
    if (kind == "missing") { reference = "-"; tolerance = escape(c.value("why", "")); }
    md += fmt::format("| {} | {} | {} | {} | {} | {} |\n", escape(c.value("name", "")), number(c.value("value", Json())),
                      reference, tolerance, c.value("passed", false) ? "pass" : "**FAIL**", escape(c.value("source", "")));
  }
  if (s.contains("skipped")) {
    md += "\nNot evaluated:\n\n";
    for (const Json& k : s.at("skipped")) md += fmt::format("- {}: {}\n", k.value("what", ""), k.value("why", ""));
  }
  md += "\n| run | metrics | wall [s] | particles | steps (adv / ac / solid) | max density deviation / Mach (t) | diverged |\n"
        "|---|---|---|---|---|---|---|\n";
  for (const Json& r : s.at("runs")) {
    std::string metrics;
    int shown = 0;
    for (auto it = r.at("metrics").begin(); it != r.at("metrics").end() && shown < 6; ++it) {
      if (it.value().is_structured()) continue;  // nested records (a theory's modes) stay in summary.json
      metrics += (metrics.empty() ? "" : ", ") + it.key() + " " + number(it.value());
      ++shown;
    }
    const Json& cost = r.at("cost");
    long long particles = 0;
    if (cost.contains("particles"))
      for (auto it = cost["particles"].begin(); it != cost["particles"].end(); ++it) particles += it.value().get<long long>();
    std::string steps = "-";
    if (cost.contains("steps"))
      steps = fmt::format("{} / {} / {}", number(cost["steps"]["advection"]), number(cost["steps"]["acoustic"]),
                          number(cost["steps"]["solid"]));
    std::string compressibility = "-";  // the fluid's extremes (weakly compressible: about 0.01 / 0.1)
    if (r.contains("compressibility") && r["compressibility"].is_object()) {
      const Json& rho = r["compressibility"]["max_density_deviation"];
      const Json& mach = r["compressibility"]["max_mach"];
      compressibility = fmt::format("{:.3f} (t = {}) / {:.2f} (t = {})", rho["value"].get<double>(), number(rho["time"]),
                                    mach["value"].get<double>(), number(mach["time"]));
    }
    std::string diverged = r.value("diverged", false) ? "**yes**" : "no";
    if (r.value("diverged", false) && r.contains("divergence") && r["divergence"].is_object())
      diverged += fmt::format(" (t = {}, {}: {})", number(r["divergence"]["time"]), number(r["divergence"]["body"]),
                              escape(number(r["divergence"]["reason"])));
    md += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", escape(r.value("case", "")), escape(metrics),
                      number(cost.value("wall_s", Json())), particles, steps, compressibility, diverged);
  }
  if (s.contains("figures") && !s["figures"].empty()) {
    md += "\n";
    for (const Json& f : s["figures"]) md += fmt::format("![{0}]({1}/{0})\n", f.get<std::string>(), name);
  }
  md += "\n";
}

}  // namespace

std::string machine_description() {
  std::string model = "unknown CPU";
  std::ifstream cpu("/proc/cpuinfo");
  for (std::string line; std::getline(cpu, line);)
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  return fmt::format("{}, {} hardware threads", model, std::thread::hardware_concurrency());
}

std::string git_commit(const std::filesystem::path& project_dir) {
  const std::string command = "git -C '" + project_dir.string() + "' rev-parse --short HEAD 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return "";
  char buffer[64] = {0};
  const bool read = std::fgets(buffer, sizeof buffer, pipe) != nullptr;
  ::pclose(pipe);
  std::string commit = read ? buffer : "";
  while (!commit.empty() && (commit.back() == '\n' || commit.back() == '\r')) commit.pop_back();
  return commit;
}

std::string markdown_report(const std::filesystem::path& run_dir, const std::vector<std::string>& suites,
                            const ReportContext& context) {
  std::string md = "# Verification report\n\n";
  md += fmt::format("- date: {:%Y-%m-%d %H:%M}\n", fmt::localtime(std::time(nullptr)));
  md += fmt::format("- mode: {}\n- machine: {}\n- threads used: {}\n", context.mode, machine_description(), context.threads);
  if (!context.commit.empty()) md += fmt::format("- project commit: {}\n", context.commit);
  if (!context.command_line.empty()) md += fmt::format("- command: `{}`\n", context.command_line);
  md += "\n| suite | verdict | checks passed | runs |\n|---|---|---|---|\n";
  std::vector<std::pair<std::string, Json>> loaded;
  for (const std::string& name : suites) {
    std::ifstream in(run_dir / name / "summary.json");
    if (!in) {
      md += fmt::format("| {} | **no summary** | - | - |\n", name);
      continue;
    }
    Json s = Json::parse(in);
    int passed = 0, total = 0;
    for (const Json& c : s.at("checks")) { ++total; passed += c.value("passed", false); }
    md += fmt::format("| {} | {} | {} of {} | {} |\n", name, s.value("passed", false) ? "PASSED" : "**FAILED**", passed, total,
                      s.at("runs").size());
    loaded.emplace_back(name, std::move(s));
  }
  md += "\n";
  for (const auto& [name, s] : loaded) suite_section(md, name, s);
  return md;
}

}  // namespace mrsph::verification
