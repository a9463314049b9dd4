#include "dream/workflows/log_workflow.h"

#include <spdlog/fmt/fmt.h>

#include "dream/run_log/log_channel_counts.h"
#include "dream/run_log/log_difference.h"
#include "dream/run_log/log_echo.h"

namespace dream::workflows {

void LogWorkflow::Info(const std::string& path) const {
  const run_log::LogChannelCounts counts = run_log::LogChannelCounts::Read(path);
  out_ << counts.path() << ": " << counts.events() << " events, " << fmt::format("{:.2f}", counts.seconds())
       << " s of log time\n";  // to 0.01 s, not "6.66667 s"
  for (const auto& [channel, c] : counts.channels()) {
    out_ << "  " << channel << ": " << c.events << " events, " << c.bytes << " bytes\n";
  }
}

bool LogWorkflow::Diff(const std::string& first_path, const std::string& first_name, const std::string& second_path,
                       const std::string& second_name, const std::regex& channels, const std::string& channels_text,
                       bool raw) const {
  const run_log::LogDifference difference =
      run_log::LogDifference::Compare({first_path, first_name}, {second_path, second_name}, channels, raw);
  for (const std::string& line : difference.differences()) out_ << line << '\n';
  out_ << (difference.same() ? "same" : "different") << " (channels matching '" << channels_text << "')\n";
  return difference.same();
}

void LogWorkflow::Echo(const std::string& path, const std::regex& channels, const std::string& channels_text,
                       long long limit) const {
  run_log::LogEcho::Options options;
  options.path = path;
  options.channels = channels;
  options.channels_text = channels_text;
  options.limit = limit;
  run_log::LogEcho::Print(options, out_, problems_);
}

}  // namespace dream::workflows
