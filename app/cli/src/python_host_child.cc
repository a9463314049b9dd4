// dream-agent --python-host: the process that hosts Python controllers for
// PythonHostProcess, which started it with the link on descriptor 3, the
// faulthandler pipe on 4 and the shared call cell on 5. Its own memq:// bus
// holds the embedded Python host; the link relays the world's messages in and
// its robots' messages out. It ends at the end of the link's stream (its
// parent stops it), when the host ends, or when its parent kills it.
#include <spdlog/spdlog.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <thread>

#include "commands.h"
#include "data_files.h"
#include "dream/config/config_error.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/message_header.h"
#include "python_host_library.h"
#include "relay_link.h"

namespace dream::cli {
namespace {

constexpr int kLinkFd = 3;
constexpr const char* kTraceFd = "4";
constexpr int kCellFd = 5;

[[noreturn]] void End(int code) {
  spdlog::default_logger()->flush();
  std::fflush(nullptr);
  // No destructors, no interpreter finalisation: nothing a controller left
  // running (a thread, a handler) can hold the exit up.
  ::_exit(code);
}

}  // namespace

int RunPythonHostChild() {
  InstallStopSignals();
  RelayLink link(kLinkFd);
  void* cell = ::mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_SHARED, kCellFd, 0);
  ::close(kCellFd);
  if (cell == MAP_FAILED) {
    link.Send('E', "error", "cannot map the call cell shared with dream");
    End(kExitRunFailed);
  }
  ::setenv("DREAM_PYTHON_TRACE_FD", kTraceFd, 1);  // read by dream.embedded.setup
  RelayLink::Frame start;
  if (!link.Receive(&start) || start.kind != 'S') End(kExitUsage);
  try {
    const nlohmann::json json = nlohmann::json::parse(start.data);
    spdlog::set_level(static_cast<spdlog::level::level_enum>(json.at("log_level").get<int>()));
    const std::string spec = json.at("spec").get<std::string>();
    const python_host::PythonAgentHost::Paths paths{DataFiles::PythonRuntimeDir(), DataFiles::PythonTypesDir()};
    const PythonHostLibrary& library = PythonHostLibrary::Get();
    library.Watch(json.at("agent_timeout_s").get<double>(), json.at("start_timeout_s").get<double>(),
                  static_cast<std::atomic<int64_t>*>(cell));
    if (json.at("check_only").get<bool>()) {
      library.Check(spec, paths);
      link.Send('R');
      End(kExitOk);
    }
    const int64_t agent_id = json.at("agent_id").get<int64_t>();
    lcm::LcmBus bus("memq://");
    // The robots' messages go to the parent; radio from elsewhere came from it.
    const lcm::Subscription to_parent = bus.Subscribe(lcm::kAgentOutboxRegex, [&](const std::string& channel,
                                                                                            const void* data, int size) {
      if (channel.rfind(lcm::kRadioChannelPrefix, 0) == 0 &&
          lcm::MessageHeader::AgentIdOf(data, static_cast<size_t>(size)).value_or(0) != agent_id) {
        return;
      }
      if (!link.Send('M', channel, data, static_cast<size_t>(size))) StopFlag().store(true);
    });
    const std::unique_ptr<python_host::PythonAgentHost> host =
        library.Create(bus, spec, json.at("robots").get<std::vector<int>>(), agent_id, paths);
    link.Send('R');
    // The world's messages, from now on (before, the link held them, in order).
    std::thread([&link, &bus] {
      RelayLink::Frame frame;
      try {
        while (link.Receive(&frame)) {
          if (frame.kind == 'M') bus.Publish(frame.channel, frame.data.data(), static_cast<int>(frame.data.size()));
        }
      } catch (const std::exception& error) {
        spdlog::error("the link to dream broke: {}", error.what());
      }
      StopFlag().store(true);  // the parent is done with this process
    }).detach();
    const double idle_timeout_s = json.at("idle_timeout_s").get<double>();
    const bool finished = host->Run(bus, StopFlag(), idle_timeout_s > 0 ? idle_timeout_s : 1e9);
    nlohmann::json done;
    done["world_finished"] = finished;
    done["last_step_answered"] = host->last_step_answered();
    done["end_detail"] = host->end_detail();
    done["report"] = host->ReportJson();
    link.Send('D', "", done.dump());
    End(kExitOk);
  } catch (const config::ConfigError& error) {
    link.Send('E', "ConfigError", error.what());
    End(kExitInputError);
  } catch (const std::exception& error) {
    link.Send('E', "error", error.what());
    End(kExitRunFailed);
  }
}

}  // namespace dream::cli
