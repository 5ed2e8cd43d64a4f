// The campaign library's entry point (campaign::RunCampaign) on the analytic sphere objective, f = Σ (x_i − 1)²,
// given as a config tree (no file): the options are checked by IsValid, every evaluation comes back with its
// variables and objective, the best is the feasible evaluation of lowest f, progress and messages go to the
// callbacks, and a call stopped at max_evaluations and resumed gives the uninterrupted history with nothing
// evaluated twice.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "campaign/run_campaign.h"
#include "io/formats/input_error.h"

namespace fs = std::filesystem;
using namespace hullopt;

namespace {

// A 2-variable COBYLA campaign on the sphere from (0, 0), 30 evaluations per start, 2 starts.
YAML::Node SphereCampaign() {
  YAML::Node c = YAML::Load(R"(
optimize:
  algorithm: LN_COBYLA
  max_evaluations: 30
  starts: 2
  seed: 3
  variables: { x1: [-2, 2], x2: [-2, 2] }
  start: { x1: 0, x2: 0 }
  objective: { analytic: sphere }
)");
  return c;
}

std::string Scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("hullopt_unit_run_campaign_" + name);
  fs::remove_all(p);
  return p.string();
}

campaign::CampaignSpec Spec() {
  return campaign::CampaignSpec::FromTree(io::CampaignCommand::kOptimize, SphereCampaign(), "<test>");
}

double Sphere(const std::vector<double>& x) { return (x[0] - 1) * (x[0] - 1) + (x[1] - 1) * (x[1] - 1); }

}  // namespace

TEST_CASE("run options are checked by IsValid, naming the field", "[campaign]") {
  campaign::CampaignRunOptions o;
  std::string e;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(e.find("out") != std::string::npos);
  o.out = "x";
  CHECK(o.IsValid(&e));
  o.max_evaluations = -1;
  CHECK_FALSE(o.IsValid(&e));
  CHECK(e.find("max_evaluations = -1") != std::string::npos);
}

TEST_CASE("a campaign from a config tree returns every evaluation and the best", "[campaign]") {
  campaign::CampaignRunOptions o;
  o.out = Scratch("whole");
  o.threads = 1;
  o.plots = false;
  long updates = 0, finished = -1;
  o.progress = [&](const campaign::CampaignProgress& p) {
    if (p.stage == campaign::CampaignProgress::Stage::kUpdate) ++updates;
    if (p.stage == campaign::CampaignProgress::Stage::kFinish) finished = p.done;
  };
  const campaign::CampaignResult r = campaign::RunCampaign(Spec(), o);
  REQUIRE(r.complete);
  // The base design (evaluation 0) and at most 30 per start.
  REQUIRE(r.history.size() >= 3);
  CHECK(r.history.size() <= 61);
  CHECK(updates == static_cast<long>(r.history.size()));
  CHECK(finished == static_cast<long>(r.history.size()));
  CHECK(r.layout.variables == std::vector<std::string>{"x1", "x2"});
  // The objective of each row is the sphere at its variables (the evaluator's formula, computed here apart);
  // same operations in the same order, so equal to the last bit.
  long best = -1;
  for (std::size_t i = 0; i < r.history.size(); ++i) {
    CHECK(r.history[i].result.objective == Sphere(r.history[i].x));
    if (r.history[i].feasible && (best < 0 || r.history[i].result.objective < r.history[best].result.objective))
      best = static_cast<long>(i);
  }
  CHECK(r.best == best);
  CHECK(r.summary["best_evaluation"].get<long>() == best);
  // The base design (0, 0) has f = 2.
  CHECK(r.history[0].result.objective == 2.0);
  CHECK(r.text.find("best objective") != std::string::npos);
  CHECK(fs::exists(fs::path(o.out) / "history.csv"));
  CHECK(fs::exists(fs::path(o.out) / "best.yaml"));
  CHECK_FALSE(fs::exists(fs::path(o.out) / "convergence.svg"));  // plots off
}

TEST_CASE("a call stopped at max_evaluations and resumed equals the uninterrupted run", "[campaign]") {
  campaign::CampaignRunOptions o;
  o.threads = 1;
  o.plots = false;
  o.out = Scratch("ref");
  const campaign::CampaignResult ref = campaign::RunCampaign(Spec(), o);
  o.out = Scratch("part");
  o.max_evaluations = 7;
  const campaign::CampaignResult part = campaign::RunCampaign(Spec(), o);
  CHECK_FALSE(part.complete);
  CHECK(part.history.size() == 7);
  CHECK_FALSE(fs::exists(fs::path(o.out) / "summary.json"));
  o.max_evaluations = 0;
  std::vector<std::string> messages;
  o.message = [&](const std::string& m) { messages.push_back(m); };
  const campaign::CampaignResult rest = campaign::RunCampaign(Spec(), o);
  REQUIRE(rest.complete);
  CHECK(rest.replayed == 7);
  CHECK(rest.summary["computed_evaluations"].get<long>() == static_cast<long>(ref.history.size()) - 7);
  REQUIRE(rest.history.size() == ref.history.size());
  for (std::size_t i = 0; i < ref.history.size(); ++i) {
    CHECK(rest.history[i].x == ref.history[i].x);
    CHECK(rest.history[i].result.objective == ref.history[i].result.objective);
    CHECK(rest.history[i].feasible == ref.history[i].feasible);
  }
  REQUIRE_FALSE(messages.empty());
  CHECK(messages[0].find("resuming: 7 evaluations") != std::string::npos);
  // resume off: a folder holding the log is refused.
  o.resume = false;
  CHECK_THROWS_AS(campaign::RunCampaign(Spec(), o), io::InputError);
}
