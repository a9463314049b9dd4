#include "dream/python_host/python_host_child.h"

#include <spdlog/spdlog.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <thread>

#include "dream/config/config_error.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/message_header.h"
#include "dream/process/data_files.h"
#include "dream/python_host/python_host_library.h"
#include "dream/python_host/relay_link.h"

namespace dream::python_host {
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

void PythonHostChild::Run(std::atomic<bool>& stop, const ExitCodes& codes) {
  RelayLink link(kLinkFd);
  void* cell = ::mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_SHARED, kCellFd, 0);
  ::close(kCellFd);
  if (cell == MAP_FAILED) {
    link.Send('E', "error", "cannot map the call cell shared with dream");
    End(codes.run_failed);
  }
  ::setenv("DREAM_PYTHON_TRACE_FD", kTraceFd, 1);  // read by dream.embedded.setup
  RelayLink::Frame start;
  if (!link.Receive(&start) || start.kind != 'S') End(codes.usage);
  try {
    const nlohmann::json json = nlohmann::json::parse(start.data);
    spdlog::set_level(static_cast<spdlog::level::level_enum>(json.at("log_level").get<int>()));
    const std::string spec = json.at("spec").get<std::string>();
    const python_embedded::PythonAgentHost::Paths paths{process::DataFiles::PythonRuntimeDir(),
                                                        process::DataFiles::PythonTypesDir()};
    const PythonHostLibrary& library = PythonHostLibrary::Get(stop);
    library.Watch(json.at("agent_timeout_s").get<double>(), json.at("start_timeout_s").get<double>(),
                  static_cast<std::atomic<int64_t>*>(cell));
    if (json.at("check_only").get<bool>()) {
      library.Check(spec, paths);
      link.Send('R');
      End(codes.ok);
    }
    const int64_t agent_id = json.at("agent_id").get<int64_t>();
    lcm::LcmBus bus("memq://");
    // The robots' messages go to the parent; radio from elsewhere came from it.
    const lcm::Subscription to_parent =
        bus.Subscribe(lcm::kAgentOutboxRegex, [&](const std::string& channel, const void* data, int size) {
          if (channel.rfind(lcm::kRadioChannelPrefix, 0) == 0 &&
              lcm::MessageHeader::AgentIdOf(data, static_cast<size_t>(size)).value_or(0) != agent_id) {
            return;
          }
          if (!link.Send('M', channel, data, static_cast<size_t>(size))) stop.store(true);
        });
    const std::unique_ptr<python_embedded::PythonAgentHost> host =
        library.Create(bus, spec, json.at("robots").get<std::vector<int>>(), agent_id, paths);
    link.Send('R');
    // The world's messages, from now on (before, the link held them, in order).
    std::thread([&link, &bus, &stop] {
      RelayLink::Frame frame;
      try {
        while (link.Receive(&frame)) {
          if (frame.kind == 'M') bus.Publish(frame.channel, frame.data.data(), static_cast<int>(frame.data.size()));
        }
      } catch (const std::exception& error) {
        spdlog::error("the link to dream broke: {}", error.what());
      }
      stop.store(true);  // the parent is done with this process
    }).detach();
    const double idle_timeout_s = json.at("idle_timeout_s").get<double>();
    const bool finished = host->Run(bus, stop, idle_timeout_s > 0 ? idle_timeout_s : 1e9);
    nlohmann::json done;
    done["world_finished"] = finished;
    done["last_step_answered"] = host->last_step_answered();
    done["end_detail"] = host->end_detail();
    done["report"] = host->ReportJson();
    link.Send('D', "", done.dump());
    End(codes.ok);
  } catch (const config::ConfigError& error) {
    link.Send('E', "ConfigError", error.what());
    End(codes.input_error);
  } catch (const std::exception& error) {
    link.Send('E', "error", error.what());
    End(codes.run_failed);
  }
}

}  // namespace dream::python_host
