#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

// Coverage-guided fuzz targets for the readers of hostile bytes: each takes
// one input, runs the reader on it, and calls Finding() when the reader broke
// a rule a sanitizer cannot see (an error that does not name its file, a
// decoded message that does not encode back to its bytes). Built as libFuzzer
// programs with -DDREAM_FUZZ=ON under clang (docs/reliability.md, "Fuzzing"),
// and replayed over tests/fuzz/corpus by fuzz_corpus_test in every build.
namespace dream::fuzz {

/// A .lcmlog file: RunLog::Read and what pictures and metrics ask of it.
void RunLogTarget(const uint8_t* data, size_t size);
/// A lab result: the first byte picks .npy (even) or .mat (odd), the rest is the file.
void LabResultTarget(const uint8_t* data, size_t size);
/// The rows of a lab result (.npy bytes) against a fixed 8-robot export:
/// ParseLabResult and the lab verifier's rules on what it gives.
void LabRowsTarget(const uint8_t* data, size_t size);
/// An LCM datagram: the first byte picks one of the seven dream types, the
/// rest is the message; also the radio payload codecs.
void LcmMessageTarget(const uint8_t* data, size_t size);
/// A run config's YAML text.
void RunConfigTarget(const uint8_t* data, size_t size);
/// `--set KEY=VALUE` arguments, one a line (at most 8), on config/go_to_goal.yaml:
/// as `dream run` applies them (OverriddenConfig, the run config, the run
/// folder's config.yaml loaded again and run as RunConfigTarget runs a
/// config) and as `dream sweep` does (SweepParameter, SweepPlan).
void SetOverrideTarget(const uint8_t* data, size_t size);

/// Prints "fuzz finding: <what>" and aborts, so libFuzzer keeps the input
/// and fuzz_corpus_test fails.
[[noreturn]] void Finding(const std::string& what);

/// Writes `size` bytes to this process's scratch file ending in `suffix`
/// (readers that take a path) and returns its path.
std::string ScratchFile(const uint8_t* data, size_t size, const std::string& suffix);

}  // namespace dream::fuzz
