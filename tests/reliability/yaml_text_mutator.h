#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace dream::testing {

/// Mutations of a YAML config's text that a careless user, a broken editor or
/// an attacker would make: values replaced by hostile scalars (huge, tiny,
/// negative, not-a-number, lists and mappings where a number belongs), numbers
/// scaled, lines deleted, duplicated (duplicate keys), swapped or re-indented,
/// document markers, anchors and aliases (self-containing, exploding,
/// undefined), deep nesting, and raw bytes (control characters, NUL, invalid
/// UTF-8, truncation). Deterministic for a seed.
class YamlTextMutator {
 public:
  explicit YamlTextMutator(uint32_t seed) : random_(seed) {}

  /// `text` with one to three mutations.
  std::string Mutate(const std::string& text);

  /// A value nested `depth` levels deep, in flow or block style.
  static std::string Nested(int depth, bool flow);

 private:
  int Below(size_t n) { return n == 0 ? 0 : static_cast<int>(random_() % n); }
  void MutateOnce(std::vector<std::string>* lines);
  std::string HostileScalar();
  std::string ScaledNumber(const std::string& number);
  /// Index of a random line holding "key: value" or "- value", or -1.
  int LineWithValue(const std::vector<std::string>& lines);

  std::mt19937 random_;
};

}  // namespace dream::testing
