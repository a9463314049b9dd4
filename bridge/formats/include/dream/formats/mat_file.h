#pragma once

#include <cstdint>
#include <string>

#include "dream/formats/npy_file.h"

namespace dream::formats {

/// Reads the real double matrix `variable` from a MATLAB .mat file (v4, v5
/// or v7.3, through libmatio) as a 2-D row-major array, for users who save
/// their lab results from MATLAB. @throws std::runtime_error naming the file
/// and what is wrong (not a .mat file, no such variable, not a real double
/// 2-D matrix, unreadable data, declared sizes the file cannot hold). Nothing
/// is allocated for the values before their count is checked against
/// `max_values` and against the file's size (at least a byte per value, or
/// zlib's best ratio for a compressed variable).
NpyArray ReadMatMatrix(const std::string& path, const std::string& variable, int64_t max_values = int64_t{1} << 26);

/// ReadMatMatrix for arrays of rank 2 up to `max_rank` (3 at most): a 3-D
/// MATLAB array d0 x d1 x d2 comes back with shape {d0, d1, d2}, row-major.
NpyArray ReadMatArray(const std::string& path, const std::string& variable, int64_t max_values, int max_rank);

/// Writes `array` (2-D) as the double matrix `variable` of a new MATLAB .mat
/// file at `path`, version 5 or (v73) 7.3 (tests and tools; not atomic).
/// @throws std::runtime_error.
void WriteMatMatrix(const std::string& path, const std::string& variable, const NpyArray& array, bool v73 = false);

}  // namespace dream::formats
