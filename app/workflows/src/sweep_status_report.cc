#include "dream/workflows/sweep_status_report.h"

namespace dream::workflows {

std::string SweepStatusReport::Text() const {
  std::string text = "sweep " + out_dir + " (" + engine + "): " + std::to_string(planned) + " runs\n";
  text += "  finished     " + std::to_string(finished) + " (" + std::to_string(succeeded) + " successful)\n";
  text += "  running      " + std::to_string(running) + "\n";
  text += "  pending      " + std::to_string(pending) + "\n";
  text += "  failed       " + std::to_string(failed) + "\n";
  if (interrupted > 0) text += "  interrupted  " + std::to_string(interrupted) + "\n";
  text += "  not started  " + std::to_string(not_started) + "\n";
  if (!problems.empty()) {
    text += "why runs did not finish:\n";
    size_t shown = 0;
    for (const auto& [why, count] : problems) {
      if (++shown > 20) {
        text += "  (" + std::to_string(problems.size() - 20) + " more reasons; see dream sweep table)\n";
        break;
      }
      text += "  " + std::to_string(count) + " x " + why + "\n";
    }
  }
  if (!note.empty()) text += "note: " + note + "\n";
  const size_t redo = failed + interrupted + not_started;
  if (running + pending > 0) {
    text += "next: wait, then dream sweep table " + out_dir + "\n";
  } else if (redo > 0) {
    text += "next: dream sweep resume " + out_dir + " runs the " + std::to_string(redo) + " runs again\n";
  } else {
    text += "next: dream sweep table " + out_dir + " (sweep.md)\n";
  }
  return text;
}

}  // namespace dream::workflows
