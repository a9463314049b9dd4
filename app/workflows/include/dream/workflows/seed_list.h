#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dream::workflows {

/// The largest seed a config accepts (`seed:` is read as a signed 64-bit number).
constexpr uint64_t kMaxSeed = 9223372036854775807ULL;
/// A sweep of more runs than this is almost certainly a typo ("1-100000000").
constexpr size_t kMaxSweepRuns = 100000;

/// Parses `--seeds`: "7", "1-20" or a comma list of both, "1,4,9-12", into
/// seeds in the order given. @throws std::invalid_argument naming the bad part
/// (not a whole number, a range that runs backwards, a seed given twice, too many).
std::vector<uint64_t> ParseSeedList(const std::string& text);

}  // namespace dream::workflows
