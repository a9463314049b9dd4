#include "dream/workflows/sweep_value_stats.h"

#include <algorithm>
#include <unordered_map>

#include "dream/world/printf_text.h"

namespace dream::workflows {
namespace {

// Groups in the order their labels first appear.
class GroupIndex {
 public:
  explicit GroupIndex(std::vector<SweepValueStats::Group>& groups) : groups_(groups) {}
  SweepValueStats::Group& operator[](const std::string& label) {
    const auto [it, added] = index_.emplace(label, groups_.size());
    if (added) {
      groups_.emplace_back();
      groups_.back().label = label;
    }
    return groups_[it->second];
  }

 private:
  std::vector<SweepValueStats::Group>& groups_;
  std::unordered_map<std::string, size_t> index_;
};

void Count(SweepValueStats::Group& group, const SweepRunResult& r) {
  ++group.runs;
  if (r.status == SweepRunResult::Status::kRan || r.status == SweepRunResult::Status::kFailed) ++group.judged;
  if (r.success) ++group.succeeded;
  if (r.status == SweepRunResult::Status::kRan && !r.goal.has_criterion) ++group.without_goal;
  if (r.status == SweepRunResult::Status::kRan && r.goal.completion_step >= 0) {
    const long long step = r.goal.completion_step;
    // The mean as a running mean, so no sum can overflow.
    ++group.completed;
    group.completion_mean += (static_cast<double>(step) - group.completion_mean) / static_cast<double>(group.completed);
    group.completion_min = group.completion_min < 0 ? step : std::min(group.completion_min, step);
    group.completion_max = std::max(group.completion_max, step);
  }
  if (r.min_distance_m && (!group.has_min_distance || *r.min_distance_m < group.closest_m)) {
    group.has_min_distance = true;
    group.closest_m = *r.min_distance_m;
    group.closest_run = r.run.name;
  }
}

std::string Cell(const std::string& text) {
  std::string cell;
  for (char c : text)
    cell += c == '|' ? std::string("\\|") : (c == '\n' || c == '\r') ? std::string(" ") : std::string(1, c);
  return cell;
}

std::string Row(const SweepValueStats::Group& g) {
  const std::string success =
      g.judged > 0 && g.without_goal == g.judged ? std::string("no goal declared")
      : g.judged > 0
          ? std::to_string(g.succeeded) + " of " + std::to_string(g.judged) + " (" +
                world::PrintfText("%.1f", 100.0 * static_cast<double>(g.succeeded) / static_cast<double>(g.judged)) +
                " %)"
          : std::string("-");
  const std::string completion = g.completed > 0
                                     ? "mean " + world::PrintfText("%.0f", g.completion_mean) + ", " +
                                           std::to_string(g.completion_min) + "-" + std::to_string(g.completion_max) +
                                           " (" + std::to_string(g.completed) + " completed)"
                                     : std::string("none completed");
  const std::string closest =
      g.has_min_distance ? world::PrintfText("%.4f", g.closest_m) + " m (" + g.closest_run + ")" : std::string("-");
  return "| " + Cell(g.label) + " | " + std::to_string(g.runs) + " | " + success + " | " + completion + " | " +
         Cell(closest) + " |\n";
}

std::string Table(const std::string& title, const std::vector<SweepValueStats::Group>& groups, size_t max_rows) {
  std::string md = "## " + title + "\n\n| " + (title == "By value" ? "value" : "values") +
                   " | runs | success | completion step | closest approach |\n|---|---|---|---|---|\n";
  for (size_t i = 0; i < groups.size() && i < max_rows; ++i) md += Row(groups[i]);
  if (groups.size() > max_rows) md += "\n(" + std::to_string(groups.size() - max_rows) + " more in sweep.md)\n";
  return md;
}

}  // namespace

SweepValueStats::SweepValueStats(const std::vector<std::string>& keys, const std::vector<SweepRunResult>& results) {
  if (keys.empty()) return;
  // By value: every key's groups together, in --set order.
  for (size_t k = 0; k < keys.size(); ++k) {
    std::vector<Group> groups;
    GroupIndex index(groups);
    for (const SweepRunResult& r : results) {
      if (k < r.run.parameters.size()) Count(index[keys[k] + "=" + r.run.parameters[k].second], r);
    }
    by_value_.insert(by_value_.end(), groups.begin(), groups.end());
  }
  if (keys.size() < 2) return;
  GroupIndex index(by_combination_);
  for (const SweepRunResult& r : results) {
    std::string label;
    for (const auto& [key, value] : r.run.parameters) label += (label.empty() ? "" : ", ") + key + "=" + value;
    Count(index[label], r);
  }
}

std::string SweepValueStats::Markdown(size_t max_rows) const {
  if (by_value_.empty()) return "";
  std::string md = Table("By value", by_value_, max_rows);
  if (!by_combination_.empty()) md += "\n" + Table("By combination", by_combination_, max_rows);
  return md;
}

}  // namespace dream::workflows
