#include "dream/bridge/mat_file.h"

#include <matio.h>

#include <cstring>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace dream::bridge {
namespace {

// libmatio reports problems through one process-wide log function; keep its
// last message (instead of printing it) so errors can name it.
thread_local std::string last_matio_message;

void CaptureMatioLog(int /*log_level*/, char* message) { last_matio_message = message != nullptr ? message : ""; }

void InstallMatioLog() {
  static std::once_flag once;
  std::call_once(once, [] { Mat_LogInitFunc("dream", CaptureMatioLog); });
}

struct MatCloser {
  void operator()(mat_t* mat) const { Mat_Close(mat); }
};
struct VarFreer {
  void operator()(matvar_t* var) const { Mat_VarFree(var); }
};

std::string MatioDetail() { return last_matio_message.empty() ? std::string() : " (libmatio: " + last_matio_message + ")"; }

}  // namespace

NpyArray ReadMatMatrix(const std::string& path, const std::string& variable) {
  InstallMatioLog();
  last_matio_message.clear();
  auto fail = [&path](const std::string& problem) { throw std::runtime_error(path + ": " + problem + MatioDetail()); };
  std::unique_ptr<mat_t, MatCloser> mat(Mat_Open(path.c_str(), MAT_ACC_RDONLY));
  if (!mat) fail("cannot open it as a MATLAB .mat file");
  std::unique_ptr<matvar_t, VarFreer> var(Mat_VarReadInfo(mat.get(), variable.c_str()));
  if (!var) fail("has no variable '" + variable + "'; save the result array under that name");
  if (var->rank != 2 || var->isComplex || var->class_type != MAT_C_DOUBLE || var->isLogical) {
    fail("variable '" + variable + "' is not a real 2-D double matrix");
  }
  const size_t rows = var->dims[0];
  const size_t columns = var->dims[1];
  if (rows > (size_t{1} << 28) || columns > (size_t{1} << 16)) fail("variable '" + variable + "' is absurdly large");
  var.reset(Mat_VarRead(mat.get(), variable.c_str()));
  if (!var || var->data == nullptr || var->data_type != MAT_T_DOUBLE || var->rank != 2 || var->dims[0] != rows ||
      var->dims[1] != columns || var->nbytes != rows * columns * sizeof(double)) {
    fail("cannot read the data of variable '" + variable + "' (damaged or cut short?)");
  }
  NpyArray array;
  array.shape = {static_cast<int64_t>(rows), static_cast<int64_t>(columns)};
  array.values.resize(rows * columns);
  const auto* data = static_cast<const double*>(var->data);  // column-major
  for (size_t r = 0; r < rows; ++r) {
    for (size_t c = 0; c < columns; ++c) array.values[r * columns + c] = data[c * rows + r];
  }
  return array;
}

void WriteMatMatrix(const std::string& path, const std::string& variable, const NpyArray& array, bool v73) {
  InstallMatioLog();
  last_matio_message.clear();
  if (array.shape.size() != 2) throw std::invalid_argument("WriteMatMatrix: needs a 2-D array");
  const auto rows = static_cast<size_t>(array.shape[0]);
  const auto columns = static_cast<size_t>(array.shape[1]);
  std::vector<double> column_major(rows * columns);
  for (size_t r = 0; r < rows; ++r) {
    for (size_t c = 0; c < columns; ++c) column_major[c * rows + r] = array.values[r * columns + c];
  }
  std::unique_ptr<mat_t, MatCloser> mat(Mat_CreateVer(path.c_str(), nullptr, v73 ? MAT_FT_MAT73 : MAT_FT_MAT5));
  if (!mat) throw std::runtime_error(path + ": cannot create the .mat file" + MatioDetail());
  size_t dims[2] = {rows, columns};
  std::unique_ptr<matvar_t, VarFreer> var(
      Mat_VarCreate(variable.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, column_major.data(), MAT_F_DONT_COPY_DATA));
  if (!var || Mat_VarWrite(mat.get(), var.get(), MAT_COMPRESSION_NONE) != 0) {
    throw std::runtime_error(path + ": cannot write variable '" + variable + "'" + MatioDetail());
  }
}

}  // namespace dream::bridge
