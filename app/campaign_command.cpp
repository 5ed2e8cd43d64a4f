#include "app/campaign_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "app/campaign_report.h"
#include "app/mpi_context.h"
#include "app/progress.h"
#include "app/run_checks.h"
#include "campaign/run_campaign.h"

namespace hullopt::app {

CLI::App* AddCampaignCommand(CLI::App& app, const CommandText& text,
                             std::function<void(const CampaignCliOptions&)> run,
                             const std::function<void(CLI::App*)>& more_options) {
  auto o = std::make_shared<CampaignCliOptions>();
  auto* cmd = AddConfigCommand(app, text, [o, run = std::move(run)](const std::string& config, const std::string& out) {
    CampaignCliOptions one = *o;
    one.config = config;
    one.out = out;
    run(one);
  });
  cmd->add_option("--threads", o->threads, "OpenMP threads per process (0 = OpenMP default)");
  if (more_options) more_options(cmd);
  cmd->add_flag("--quiet", o->quiet, "no progress output");
  cmd->add_flag("--no-plots", o->no_plots, "write the numbers only: no SVG figures and no report.html");
  cmd->add_flag("--profile", o->profile,
                "where the evaluations' time goes: mean wall time per evaluation of each stage (hull, attitude, "
                "panelling, kernel, solve, seas, resistance, log) on stderr and in summary.json");
  return cmd;
}

void RunCampaignCommand(io::CampaignCommand command, const CampaignCliOptions& o) {
  campaign::CampaignRunOptions options;
  options.out = o.out;
  options.threads = o.threads;
  options.force = ForceGiven();
  options.quiet = o.quiet;
  options.plots = !o.no_plots;
  options.chunk = o.chunk;
  options.profile = o.profile;
  options.comm = &ProcessComm();
  std::unique_ptr<Progress> bar;
  options.progress = [&bar](const campaign::CampaignProgress& p) {
    switch (p.stage) {
      case campaign::CampaignProgress::Stage::kStart:
        bar = std::make_unique<Progress>(p.label, p.total);
        break;
      case campaign::CampaignProgress::Stage::kUpdate:
        if (bar) bar->Update(p.done, p.replayed);
        break;
      case campaign::CampaignProgress::Stage::kFinish:
        if (bar) bar->Finish(p.done, p.replayed);
        break;
    }
  };
  options.message = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
  options.write_report = [](const campaign::CampaignReportRequest& r) {
    WriteCampaignReport(r.out, r.command, r.config_file, r.campaign_warnings, r.active_set);
  };
  const campaign::CampaignResult result =
      campaign::RunCampaign(campaign::CampaignSpec::FromFile(command, o.config), options);
  if (MpiRank() != 0) return;
  if (o.profile) std::fputs(result.profile_text.c_str(), stderr);
  if (!o.quiet) std::fputs(result.text.c_str(), stdout);
  if (!result.sweep.empty()) std::fputs(result.sweep.c_str(), stdout);
}

}  // namespace hullopt::app
