#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dream::formats {

/// A float64 array in C (row-major) order: what numpy's .npy format holds
/// with dtype '<f8' and fortran_order False, the only kind the bridge uses.
struct NpyArray {
  std::vector<int64_t> shape;
  std::vector<double> values;  ///< row-major, product(shape) values

  int64_t size() const;
};

/// The bytes of a .npy file (format version 1.0, header padded to 64 bytes,
/// '<f8', C order) holding `array`. @throws std::invalid_argument if the
/// shape does not match the number of values.
std::string EncodeNpy(const NpyArray& array);

/// The bytes of a .npy file holding `bytes` as a 1-D uint8 array ('|u1'):
/// how text (JSON) travels to the submission script, which reads it with
/// np.load(..., allow_pickle=False) and decodes it as UTF-8.
std::string EncodeNpyBytes(const std::string& bytes);

/// Parses .npy bytes, strictly: magic, version 1.0/2.0/3.0, a header dict
/// with exactly descr '<f8', fortran_order and a shape tuple, and exactly
/// product(shape) * 8 bytes of data after it. A Fortran-order array (as
/// scipy.io.loadmat gives them) is returned in C order, as numpy reads it.
/// Values may be NaN/inf (callers decide). @throws std::runtime_error
/// "<name>: <problem>" naming what is wrong (truncated, foreign dtype, ...).
NpyArray DecodeNpy(const std::string& bytes, const std::string& name);

/// DecodeNpy of the file at `path`; refuses files over `max_bytes` before
/// reading them. @throws std::runtime_error naming the path.
NpyArray ReadNpyFile(const std::string& path, int64_t max_bytes = int64_t{1} << 32);

}  // namespace dream::formats
