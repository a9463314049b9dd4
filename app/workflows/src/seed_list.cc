#include "dream/workflows/seed_list.h"

#include <set>
#include <stdexcept>

namespace dream::workflows {
namespace {

uint64_t ParseSeed(const std::string& text, const std::string& part) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
    throw std::invalid_argument("'" + part + "' is not a seed, a range like 1-20 or a list like 1,4,9-12 " +
                                "(seeds are whole numbers >= 0)");
  }
  // Digits only, so the one way stoull can fail is overflow.
  if (text.size() > 19 || std::stoull(text) > kMaxSeed) {
    throw std::invalid_argument("seed " + text + " is too large (at most " + std::to_string(kMaxSeed) + ")");
  }
  return std::stoull(text);
}

}  // namespace

std::vector<uint64_t> ParseSeedList(const std::string& text) {
  if (text.empty()) throw std::invalid_argument("no seeds given; write 7, 1-20 or 1,4,9-12");
  std::vector<uint64_t> seeds;
  std::set<uint64_t> seen;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (part.empty()) throw std::invalid_argument("empty item in seed list '" + text + "'");
    const size_t dash = part.find('-');
    uint64_t first = 0;
    uint64_t last = 0;
    if (dash == std::string::npos) {
      first = last = ParseSeed(part, part);
    } else {
      first = ParseSeed(part.substr(0, dash), part);
      last = ParseSeed(part.substr(dash + 1), part);
      if (last < first) {
        throw std::invalid_argument("range " + part + " runs backwards; write " + std::to_string(last) + "-" +
                                    std::to_string(first));
      }
    }
    if (last - first >= kMaxSweepRuns || seeds.size() + (last - first) >= kMaxSweepRuns) {
      throw std::invalid_argument("'" + text + "' gives more than " + std::to_string(kMaxSweepRuns) + " seeds");
    }
    for (uint64_t seed = first;; ++seed) {
      if (!seen.insert(seed).second) {
        throw std::invalid_argument("seed " + std::to_string(seed) + " is given twice in '" + text + "'");
      }
      seeds.push_back(seed);
      if (seed == last) break;
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return seeds;
}

}  // namespace dream::workflows
