#include <spdlog/spdlog.h>

#include <memory>
#include <numeric>

#include "hosted_agents.h"
#include "dream/session/run_exit_code.h"
#include "command_line.h"
#include "commands.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_url.h"
#include "run_output.h"
#include "run_view.h"
#include "shared_options.h"

namespace dream::cli {

int RunEmbedded(const RunArgs& args) {
  const std::unique_ptr<session::RunSession> run = OpenRunSession(args);
  const run_config::RunConfig& config = run->config();
  CheckStartupDrive(config);
  // One process: the world and every agent share one bus, memq:// unless the
  // user asks for a real transport.
  lcm::LcmBus bus(args.lcm_url.empty() ? "memq://" : lcm::ResolveLcmUrl(args.lcm_url));
  const std::string out_dir = PrepareOutputDir(args, config);
  std::vector<int> ids(static_cast<size_t>(config.num_robots));
  std::iota(ids.begin(), ids.end(), 0);
  const HostedAgents agents(bus, config, ids, run->factory(),
                            {config.sim.agent_timeout_s, config.sim.start_timeout_s, 0.0});
  std::unique_ptr<RunView> view;
  if (args.view) view = std::make_unique<RunView>(bus, config, args.view_bind, args.view_port, args.view_fps);
  const session::RunResult result = run->Run(bus, {out_dir, ConfigTextForRunFolder(args, config)});
  if (view) view->ShowEndOf(out_dir);
  return session::ExitCodeOf(result);
}

int RunSimOnly(const RunArgs& args) {
  const std::unique_ptr<session::RunSession> run = OpenRunSession(args);
  CheckStartupDrive(run->config());
  lcm::LcmBus bus(lcm::ResolveLcmUrl(args.lcm_url));
  const std::string out_dir = PrepareOutputDir(args, run->config());
  return session::ExitCodeOf(run->Run(bus, {out_dir, ConfigTextForRunFolder(args, run->config())}));
}

void DeclareRunCommand(CommandLine& line) {
  const auto [command, args] = AddRunCommand(
      line, "run",
      "Run an experiment in one process: the simulator and every robot's agent on one bus.\n"
      "Example: dream run config/go_to_goal.yaml --seed 7 --set controller.max_speed_mps=0.1\n"
      "Watch it: dream run config/go_to_goal.yaml --view (then open http://127.0.0.1:8077/)",
      RunEmbedded, "LCM URL (default memq://, in-process)");
  command->add_flag("--view", args->view,
                    "Serve the live arena while the run runs (dream view; paced to real time unless --pace)");
  command->add_option("--view-port", args->view_port, "Port of --view's page (0: any free port)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  command->add_option("--view-fps", args->view_fps,
                      "Frames a second --view's page gets and draws at most; fewer cost the machine less\n"
                      "(default: 30; 10 while the run goes faster than twice real time, 5 beyond ten times)")
      ->check(CLI::Range(1, view::FrameRates::kMax));
  command->add_option("--view-bind", args->view_bind,
                      "Address --view listens on; 127.0.0.1 (the default) is this machine only,\n"
                      "0.0.0.0 exposes the page to the network on purpose")
      ->capture_default_str();
}

void DeclareSimCommand(CommandLine& line) {
  AddRunCommand(line, "sim",
                "Run only the simulator; agents run elsewhere (dream agent) on the same LCM URL.\n"
                "Example: dream sim config/go_to_goal.yaml --lcm-url 'udpm://239.255.76.67:7667?ttl=0'",
                RunSimOnly, "LCM URL (default $LCM_DEFAULT_URL, else udpm://239.255.76.67:7667?ttl=0)");
}

}  // namespace dream::cli
