#pragma once

#include <iostream>
#include <ostream>
#include <string>

namespace dream::workflows {

/// `dream compare`: a simulated run and its lab run side by side
/// (bridge::CompareRunsAndWrite): tracking error per robot, closest
/// approach, violations and the experiment's metrics, written as
/// comparison.json and comparison.png and printed.
class CompareWorkflow {
 public:
  struct Options {
    std::string first_dir;           ///< the simulated run
    std::string second_dir;          ///< the lab run
    std::string out_dir;             ///< empty: second_dir
    std::string python_runtime_dir;  ///< a Python controller's own metrics ("": the built-in kinds' only)
  };

  explicit CompareWorkflow(std::ostream& out = std::cout) : out_(out) {}

  /// @throws std::runtime_error naming the run folder that cannot be read.
  void Compare(const Options& options) const;

 private:
  std::ostream& out_;
};

}  // namespace dream::workflows
