#include "report/regression.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

using namespace mrsph::verification;
using Json = nlohmann::ordered_json;

namespace {

std::filesystem::path write_run(const std::string& name, double strouhal, bool diverged = false) {
  const auto dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::create_directories(dir / "turek-hron");
  const Json summary = {{"suite", "turek-hron"},
                        {"runs", Json::array({{{"case", "III"}, {"diverged", diverged},
                                               {"metrics", {{"strouhal", strouhal}, {"amplitude_y", 0.84}}}}})}};
  std::ofstream(dir / "turek-hron" / "summary.json") << summary.dump(2);
  return dir;
}

const Json kRules = {{"turek-hron", {{"strouhal", {{"tolerance", 0.004}, {"relative", 0.0}, {"reason", "spread"}}}}}};

}  // namespace

TEST_CASE("The regression check passes within tolerance and fails beyond it", "[regression]") {
  const Json baseline = make_baseline(write_run("mrsph_reg_base", 0.1840), kRules);
  REQUIRE(baseline["suites"]["turek-hron"]["III"]["strouhal"]["value"].get<double>() == Approx(0.1840));

  const auto within = compare_to_baseline(baseline, write_run("mrsph_reg_within", 0.1870));
  REQUIRE(within.size() == 1);
  CHECK(within[0].passed);

  const auto beyond = compare_to_baseline(baseline, write_run("mrsph_reg_beyond", 0.1890));  // moved by 0.005 > 0.004
  REQUIRE(beyond.size() == 1);
  CHECK_FALSE(beyond[0].passed);
  CHECK(regression_report(beyond).find("REGRESSED") != std::string::npos);

  const auto diverged = compare_to_baseline(baseline, write_run("mrsph_reg_diverged", 0.1840, true));
  CHECK_FALSE(diverged[0].passed);
  CHECK(diverged[0].note == "the run diverged");

  const auto missing = compare_to_baseline(baseline, std::filesystem::temp_directory_path() / "mrsph_reg_nothing");
  CHECK_FALSE(missing[0].passed);
}

TEST_CASE("Relative tolerances scale with the baseline", "[regression]") {
  const Json rules = {{"turek-hron", {{"strouhal", {{"tolerance", 0.0}, {"relative", 0.01}}}}}};
  const Json baseline = make_baseline(write_run("mrsph_reg_rel_base", 0.2), rules);
  CHECK(compare_to_baseline(baseline, write_run("mrsph_reg_rel_ok", 0.2019))[0].passed);
  CHECK_FALSE(compare_to_baseline(baseline, write_run("mrsph_reg_rel_bad", 0.2021))[0].passed);
}
