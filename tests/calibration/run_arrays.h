#pragma once

#include "dream/calibration/calibration_run.h"
#include "dream/formats/npy_file.h"

namespace dream::calibration::test_support {

// A run as the lab's files hold it: poses 3 x N x T and commands 2 x N x T,
// in C order (the tests that need Fortran order or other shapes reorder these).
void ArraysOf(const CalibrationRun& run, formats::NpyArray* poses, formats::NpyArray* commands);

}  // namespace dream::calibration::test_support
