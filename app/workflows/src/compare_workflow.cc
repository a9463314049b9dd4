#include "dream/workflows/compare_workflow.h"

#include "dream/bridge/run_comparison.h"

namespace dream::workflows {

void CompareWorkflow::Compare(const Options& options) const {
  const std::string out_dir = options.out_dir.empty() ? options.second_dir : options.out_dir;
  const bridge::RunComparison comparison =
      bridge::CompareRunsAndWrite(options.first_dir, options.second_dir, out_dir, options.python_runtime_dir);
  out_ << comparison.Text() << "\nwritten: " << out_dir << "/comparison.json, " << out_dir << "/comparison.png\n";
}

}  // namespace dream::workflows
