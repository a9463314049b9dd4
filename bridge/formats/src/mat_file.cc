#include "dream/formats/mat_file.h"

#include <dlfcn.h>
#include <matio.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "dream/files/regular_file.h"
#include "mat4_layout.h"

namespace dream::formats {
namespace {

// libmatio, loaded the first time a .mat file is read or written: linked,
// it and what it needs (HDF5, curl, GnuTLS, Kerberos, LDAP: some 40
// libraries, all bound at start-up) would add ~7 ms to every dream command.
struct Matio {
  decltype(&::Mat_LogInitFunc) LogInitFunc;
  decltype(&::Mat_Open) Open;
  decltype(&::Mat_CreateVer) CreateVer;
  decltype(&::Mat_Close) Close;
  decltype(&::Mat_GetVersion) GetVersion;
  decltype(&::Mat_VarReadInfo) VarReadInfo;
  decltype(&::Mat_VarReadDataLinear) VarReadDataLinear;
  decltype(&::Mat_VarCreate) VarCreate;
  decltype(&::Mat_VarWrite) VarWrite;
  decltype(&::Mat_VarFree) VarFree;

  /// @throws std::runtime_error naming the library when it cannot be loaded.
  static const Matio& Get() {
    static const Matio matio = Load();
    return matio;
  }

 private:
  static Matio Load() {
    void* library = dlopen(DREAM_MATIO_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) {
      throw std::runtime_error(std::string("cannot load ") + DREAM_MATIO_SONAME + " for .mat files: " + dlerror());
    }
    auto symbol = [library](auto& function, const char* name) {
      function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(dlsym(library, name));
      if (function == nullptr) throw std::runtime_error(std::string(DREAM_MATIO_SONAME) + " has no " + name);
    };
    Matio matio{};
    symbol(matio.LogInitFunc, "Mat_LogInitFunc");
    symbol(matio.Open, "Mat_Open");
    symbol(matio.CreateVer, "Mat_CreateVer");
    symbol(matio.Close, "Mat_Close");
    symbol(matio.GetVersion, "Mat_GetVersion");
    symbol(matio.VarReadInfo, "Mat_VarReadInfo");
    symbol(matio.VarReadDataLinear, "Mat_VarReadDataLinear");
    symbol(matio.VarCreate, "Mat_VarCreate");
    symbol(matio.VarWrite, "Mat_VarWrite");
    symbol(matio.VarFree, "Mat_VarFree");
    return matio;  // the library stays loaded for the process
  }
};

// libmatio reports problems through one process-wide log function; keep its
// last message (instead of printing it) so errors can name it.
thread_local std::string last_matio_message;

void CaptureMatioLog(int /*log_level*/, char* message) { last_matio_message = message != nullptr ? message : ""; }

void InstallMatioLog() {
  static std::once_flag once;
  std::call_once(once, [] { Matio::Get().LogInitFunc("dream", CaptureMatioLog); });
}

struct MatCloser {
  void operator()(mat_t* mat) const { Matio::Get().Close(mat); }
};
struct VarFreer {
  void operator()(matvar_t* var) const { Matio::Get().VarFree(var); }
};

/// libmatio's last message; of an HDF5 error stack (v7.3 files) only its last
/// "minor:" line, e.g. "File has been truncated".
std::string MatioDetail() {
  if (last_matio_message.empty()) return std::string();
  std::string message = last_matio_message;
  const size_t minor = message.rfind("minor: ");
  if (minor != std::string::npos) message = "HDF5: " + message.substr(minor + 7);
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  return " (libmatio: " + message + ")";
}

// MAT-file v5 data types (the "mi" codes of MathWorks' format description).
constexpr uint32_t kMiInt8 = 1;
constexpr uint32_t kMiInt32 = 5;
constexpr uint32_t kMiUint32 = 6;
constexpr uint32_t kMiMatrix = 14;
constexpr uint32_t kMiCompressed = 15;
constexpr size_t kMat5HeaderSize = 128;
// How much of a compressed matrix is inflated to check its header: MATLAB's
// names have at most 63 characters and a lab result has two dimensions.
constexpr size_t kPeekBytes = 4096;
// zlib's best: about 1032 bytes come out of one, so a compressed part can
// never inflate past this many times its size.
constexpr uint64_t kMaxDeflateRatio = 1032;

/// Bytes per element of a numeric v5 data type, 0 for the others.
size_t NumericSize(uint32_t type) {
  switch (type) {
    case 1:
    case 2:
      return 1;  // miINT8, miUINT8
    case 3:
    case 4:
      return 2;  // miINT16, miUINT16
    case 5:
    case 6:
    case 7:
      return 4;  // miINT32, miUINT32, miSINGLE
    case 9:
    case 12:
    case 13:
      return 8;  // miDOUBLE, miINT64, miUINT64
    default:
      return 0;
  }
}

/// A v5 data element's tag: type, byte count and where its data lies.
struct Mat5Element {
  uint32_t type = 0;
  uint64_t size = 0;  ///< bytes of data
  uint64_t data = 0;  ///< offset of the data in the file
  uint64_t end = 0;   ///< offset after it, padding included
};

/// Walks the declared sizes of a MAT-file v5 against the bytes it has, so a
/// file cut short or with a forged size is refused before libmatio reads it
/// (libmatio reads a short variable without an error, into uninitialised memory).
class Mat5Layout {
 public:
  Mat5Layout(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {
    swap_ = bytes_[126] == 'M' && bytes_[127] == 'I';
  }
  /// The same walk over `bytes` taken from inside a file of byte order `swap`.
  Mat5Layout(const std::string& path, const std::string& bytes, bool swap) : path_(path), bytes_(bytes), swap_(swap) {}

  /// Every top-level element must be a (compressed) matrix that fits in the
  /// file; the uncompressed `variable`'s parts must agree with its dims.
  void Check(const std::string& variable) const {
    uint64_t offset = kMat5HeaderSize;
    for (int index = 0; offset < bytes_.size(); ++index) {
      const Mat5Element element = Tag(offset, "top-level element " + std::to_string(index), bytes_.size(), true);
      if (element.type != kMiMatrix && element.type != kMiCompressed) {
        Fail("top-level element " + std::to_string(index) + " at byte " + std::to_string(offset) + " has type " +
             std::to_string(element.type) + "; a MAT-file holds matrices (14) and compressed matrices (15) only");
      }
      if (element.type == kMiMatrix) CheckMatrix(element, variable, index);
      if (element.type == kMiCompressed) CheckCompressed(element, index);
      offset = element.end;
    }
  }

 private:
  [[noreturn]] void Fail(const std::string& problem) const {
    throw std::runtime_error(path_ + ": " + problem + " (damaged or cut short?)");
  }

  uint32_t Word(uint64_t offset) const {
    uint32_t value = 0;
    std::memcpy(&value, bytes_.data() + offset, 4);
    return swap_ ? __builtin_bswap32(value) : value;
  }

  /// The tag at `offset` of an element that must end by `limit`. Top-level
  /// elements are padded to 8 bytes except compressed ones; a file may end
  /// in the padding of its last element.
  Mat5Element Tag(uint64_t offset, const std::string& what, uint64_t limit, bool top_level) const {
    if (limit < offset + 8) {
      Fail(what + " at byte " + std::to_string(offset) +
           " is cut short inside its 8-byte tag (the element ends at byte " + std::to_string(limit) + ")");
    }
    Mat5Element element;
    const uint32_t first = Word(offset);
    if ((first >> 16) != 0) {  // small data element: size and type in one word, up to 4 bytes of data
      element.type = first & 0xffff;
      element.size = first >> 16;
      element.data = offset + 4;
      element.end = offset + 8;
      if (element.size > 4)
        Fail(what + " at byte " + std::to_string(offset) + " is a small element of " + std::to_string(element.size) +
             " bytes; at most 4 fit");
      return element;
    }
    element.type = first;
    element.size = Word(offset + 4);
    element.data = offset + 8;
    const uint64_t data_end = element.data + element.size;
    if (data_end > limit) {
      Fail(what + " at byte " + std::to_string(offset) + " declares " + std::to_string(element.size) +
           " bytes of data, but only " + std::to_string(limit - element.data) + " follow");
    }
    const bool padded = !(top_level && element.type == kMiCompressed);
    element.end = padded ? std::min<uint64_t>(limit, (data_end + 7) / 8 * 8) : data_end;
    return element;
  }

  /// libmatio inflates a compressed matrix's header and allocates the name
  /// length and dimensions it declares: the header must be a matrix whose
  /// flags, dimensions and name lie within its first kPeekBytes inflated.
  void CheckCompressed(const Mat5Element& element, int index) const {
    const std::string what =
        "compressed element " + std::to_string(index) + " at byte " + std::to_string(element.data - 8);
    std::string inflated(kPeekBytes, '\0');
    z_stream stream{};
    if (inflateInit(&stream) != Z_OK) Fail(what + ": zlib cannot start");
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes_.data() + element.data));
    stream.avail_in = static_cast<uInt>(std::min<uint64_t>(element.size, std::numeric_limits<uInt>::max()));
    stream.next_out = reinterpret_cast<Bytef*>(inflated.data());
    stream.avail_out = static_cast<uInt>(inflated.size());
    const int status = inflate(&stream, Z_SYNC_FLUSH);
    inflated.resize(inflated.size() - stream.avail_out);
    inflateEnd(&stream);
    if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR) {
      Fail(what + " is not zlib data (zlib: " + (stream.msg != nullptr ? stream.msg : std::to_string(status)) + ")");
    }
    if (inflated.size() < 8) Fail(what + " inflates to " + std::to_string(inflated.size()) + " bytes, not a matrix");
    const Mat5Layout inner(path_, inflated, swap_);
    // The matrix may be longer than what was inflated; its header may not.
    const Mat5Element matrix = inner.Tag(0, what + ": the matrix inside", UINT64_MAX, false);
    if (matrix.type != kMiMatrix) {
      Fail(what + " holds data type " + std::to_string(matrix.type) + ", not a matrix (14)");
    }
    if (matrix.size > element.size * kMaxDeflateRatio) {
      Fail(what + " says it inflates to " + std::to_string(matrix.size) + " bytes; its " +
           std::to_string(element.size) + " bytes cannot hold that much");
    }
    (void)inner.CheckHeader(matrix, what + " (inflated, first " + std::to_string(inflated.size()) + " bytes)",
                            std::min<uint64_t>(inflated.size(), matrix.data + matrix.size));
  }

  /// The first three parts of a matrix.
  struct Header {
    Mat5Element flags;
    Mat5Element dims;
    Mat5Element name;
    uint32_t matrix_class = 0;  ///< mxDOUBLE_CLASS 6, mxCELL_CLASS 1, ...
    uint64_t count = 1;         ///< the product of the dimensions, at most 2^40
    std::string shape;          ///< "2 x 3"
  };

  /// A matrix's flags, dimensions and name, the parts libmatio reads first
  /// and allocates by: each a whole tag within `limit` (the element's end, or
  /// what was inflated), of the types and sizes every MAT-file v5 array has
  /// (flags: miUINT32 x 2; dimensions: miINT32, 4 bytes each, two or more; name: miINT8).
  Header CheckHeader(const Mat5Element& matrix, const std::string& what, uint64_t limit) const {
    Header header;
    header.flags = Tag(matrix.data, what + ": its array flags", limit, false);
    if (header.flags.type != kMiUint32 || header.flags.size != 8) {
      Fail(what + ": its array flags are " + std::to_string(header.flags.size) + " bytes of type " +
           std::to_string(header.flags.type) + ", not 8 bytes of miUINT32 (6)");
    }
    header.dims = Tag(header.flags.end, what + ": its dimensions", limit, false);
    if (header.dims.type != kMiInt32 || header.dims.size % 4 != 0 || header.dims.size < 8) {
      Fail(what + ": its dimensions are " + std::to_string(header.dims.size) + " bytes of type " +
           std::to_string(header.dims.type) + ", not miINT32 (5), 4 bytes for each of two or more");
    }
    header.name = Tag(header.dims.end, what + ": its name", limit, false);
    if (header.name.type != kMiInt8) {
      Fail(what + ": its name has type " + std::to_string(header.name.type) + ", not miINT8 (1)");
    }
    for (uint64_t d = 0; d < header.dims.size / 4; ++d) {
      const auto extent = static_cast<int32_t>(Word(header.dims.data + 4 * d));
      if (extent < 0) Fail(what + ": dimension " + std::to_string(d) + " is " + std::to_string(extent));
      header.shape += (d == 0 ? "" : " x ") + std::to_string(extent);
      constexpr uint64_t kMaxCount = uint64_t{1} << 40;  // far past any file we read, and no overflow below
      const auto factor = static_cast<uint64_t>(extent);
      header.count = factor != 0 && header.count > kMaxCount / factor ? kMaxCount : header.count * factor;
    }
    // libmatio allocates a cell's or struct's elements by its dimensions: the
    // matrix must have room for them, a byte per value at least (a tag per
    // element for cells, structs and objects). Sparse matrices store only nzmax values.
    header.matrix_class = Word(header.flags.data) & 0xff;
    constexpr uint32_t kMxSparseClass = 5;
    const uint64_t per_value = header.matrix_class >= 1 && header.matrix_class <= 3 ? 8 : 1;
    if (header.matrix_class != kMxSparseClass && header.count > matrix.size / per_value) {
      Fail(what + ": dimensions " + header.shape + " (class " + std::to_string(header.matrix_class) + ") need " +
           std::to_string(per_value) + " byte(s) per value, but the matrix has " + std::to_string(matrix.size));
    }
    return header;
  }

  void CheckMatrix(const Mat5Element& matrix, const std::string& variable, int index) const {
    if (matrix.size == 0) return;  // an empty matrix element (MATLAB writes them for empty cells)
    const uint64_t limit = matrix.data + matrix.size;
    const Header header =
        CheckHeader(matrix, "matrix " + std::to_string(index) + " at byte " + std::to_string(matrix.data - 8), limit);
    if (bytes_.substr(header.name.data, header.name.size) != variable) return;
    constexpr uint32_t kMxDoubleClass = 6;
    if (header.matrix_class != kMxDoubleClass) return;  // refused by class below, with libmatio's reading of it
    const std::string what = "variable '" + variable + "'";
    const Mat5Element real = Tag(header.name.end, what + "'s real part", limit, false);
    const size_t element_size = NumericSize(real.type);
    if (element_size == 0)
      Fail(what + ": its real part has data type " + std::to_string(real.type) + ", not a number type");
    if (real.size != header.count * element_size) {
      Fail(what + ": dimensions " + header.shape + " hold " + std::to_string(header.count) +
           " values, but its real part has " + std::to_string(real.size) + " bytes of " + std::to_string(element_size) +
           "-byte numbers (" + std::to_string(real.size / element_size) + " values)");
    }
  }

  const std::string& path_;
  const std::string& bytes_;
  bool swap_ = false;
};

/// The file's bytes, refusing more than any lab result holds.
std::string ReadAll(files::RegularFile& file) {
  constexpr std::uintmax_t kMaxBytes = std::uintmax_t{1} << 31;
  if (file.size() > kMaxBytes) {
    throw std::runtime_error(file.path() + ": " + std::to_string(file.size()) + " bytes is larger than any lab result");
  }
  return file.ReadAll(kMaxBytes);
}

/// A 128-byte MATLAB header of version `major` (1: v5/v7, 2: v7.3, HDF5).
bool HasMatHeader(const std::string& bytes, char major) {
  if (bytes.size() < kMat5HeaderSize) return false;
  const bool endian_mark = (bytes[126] == 'I' && bytes[127] == 'M') || (bytes[126] == 'M' && bytes[127] == 'I');
  const bool version = (bytes[124] == 0x00 && bytes[125] == major) || (bytes[124] == major && bytes[125] == 0x00);
  return endian_mark && version;
}

bool IsMat5(const std::string& bytes) { return HasMatHeader(bytes, 0x01); }
bool IsMat73(const std::string& bytes) { return HasMatHeader(bytes, 0x02); }

/// Checks the file's layout before libmatio reads it (which trusts what the
/// file declares); returns its size. @throws std::runtime_error naming the path.
uint64_t CheckMatLayout(files::RegularFile& file, const std::string& variable) {
  const std::string& path = file.path();
  const std::string bytes = ReadAll(file);
  if (bytes.size() >= 116 && bytes.compare(0, 10, "MATLAB 5.0") == 0 && !IsMat5(bytes)) {
    throw std::runtime_error(path + ": a MATLAB 5.0 MAT-file header, but cut short or damaged before byte 128 " +
                             "(the version and byte-order marks)");
  }
  if (IsMat5(bytes)) {
    Mat5Layout(path, bytes).Check(variable);
  } else if (!IsMat73(bytes) || Mat4Layout::ReadableAsV4(bytes)) {
    Mat4Layout(path, bytes).Check();
  }
  constexpr size_t kHdf5Offset = 512;  // v7.3: a 512-byte user block (the MATLAB header), then HDF5
  if (IsMat73(bytes) && (bytes.size() < kHdf5Offset + 8 || bytes.compare(kHdf5Offset, 8, "\x89HDF\r\n\x1a\n") != 0)) {
    throw std::runtime_error(path +
                             ": a MATLAB 7.3 MAT-file header, but no HDF5 data at byte 512 (damaged or cut short?)");
  }
  return bytes.size();
}

}  // namespace

NpyArray ReadMatMatrix(const std::string& path, const std::string& variable, int64_t max_values) {
  return ReadMatArray(path, variable, max_values, 2);
}

NpyArray ReadMatArray(const std::string& path, const std::string& variable, int64_t max_values, int max_rank) {
  max_rank = std::clamp(max_rank, 2, 3);
  InstallMatioLog();
  last_matio_message.clear();
  auto fail = [&path](const std::string& problem) { throw std::runtime_error(path + ": " + problem + MatioDetail()); };
  // Opened once, without blocking (a FIFO or device is refused): libmatio
  // then reopens this very file by its descriptor's name, not the path.
  files::RegularFile file(path);
  const uint64_t file_size = CheckMatLayout(file, variable);
  std::unique_ptr<mat_t, MatCloser> mat(Matio::Get().Open(file.OpenedName().c_str(), MAT_ACC_RDONLY));
  if (!mat) fail("cannot open it as a MATLAB .mat file");
  std::unique_ptr<matvar_t, VarFreer> var(Matio::Get().VarReadInfo(mat.get(), variable.c_str()));
  if (!var && !last_matio_message.empty()) fail("cannot read variable '" + variable + "' (damaged or cut short?)");
  if (!var) fail("has no variable '" + variable + "'; save the result array under that name");
  if (var->rank < 2 || var->rank > max_rank || var->isComplex || var->class_type != MAT_C_DOUBLE || var->isLogical) {
    fail("variable '" + variable + "' is not a real " +
         (max_rank == 2 ? std::string("2-D") : "2-D to " + std::to_string(max_rank) + "-D") + " double array (rank " +
         std::to_string(var->rank) + ", class " + std::to_string(static_cast<int>(var->class_type)) +
         (var->isComplex ? ", complex" : "") + (var->isLogical ? ", logical" : "") + ")");
  }
  const size_t rows = var->dims[0];
  const size_t columns = var->dims[1];
  const size_t pages = var->rank == 3 ? var->dims[2] : 1;
  if (rows > (size_t{1} << 28) || columns > (size_t{1} << 16) || pages > (size_t{1} << 28) ||
      rows * columns > (size_t{1} << 28) || rows * columns * pages > (size_t{1} << 28)) {
    fail("variable '" + variable + "' is absurdly large: " + std::to_string(rows) + " x " + std::to_string(columns) +
         (var->rank == 3 ? " x " + std::to_string(pages) : std::string()));
  }
  const size_t count = rows * columns * pages;
  const std::string declared = "variable '" + variable + "' is " + std::to_string(rows) + " x " +
                               std::to_string(columns) +
                               (var->rank == 3 ? " x " + std::to_string(pages) : std::string());
  if (count > static_cast<uint64_t>(max_values)) {
    fail(declared + ": more than the " + std::to_string(max_values) + " values a result of this export can have");
  }
  // A value takes a byte of the file at least (MATLAB may store doubles as
  // smaller integers); compressed, kMaxDeflateRatio bytes at most from one.
  const bool compressed =
      var->compression == MAT_COMPRESSION_ZLIB || Matio::Get().GetVersion(mat.get()) == MAT_FT_MAT73;
  const uint64_t holdable = compressed ? file_size * kMaxDeflateRatio / sizeof(double) : file_size;
  if (count > holdable) {
    fail(declared + ", but the file's " + std::to_string(file_size) + " bytes cannot hold " + std::to_string(count) +
         " values (damaged or cut short?)");
  }
  // Read twice into buffers filled with two different patterns: libmatio
  // does not report every short read, and a value it did not read from the
  // file keeps the pattern, so the two reads differ.
  std::vector<double> first(count, 1.0e300);
  std::vector<double> second(count, -2.0e-300);
  const int edge = static_cast<int>(count);
  if (count > 0 && (Matio::Get().VarReadDataLinear(mat.get(), var.get(), first.data(), 0, 1, edge) != 0 ||
                    Matio::Get().VarReadDataLinear(mat.get(), var.get(), second.data(), 0, 1, edge) != 0 ||
                    std::memcmp(first.data(), second.data(), count * sizeof(double)) != 0)) {
    fail("cannot read the " + std::to_string(rows) + " x " + std::to_string(columns) + " values of variable '" +
         variable + "' (damaged or cut short?)");
  }
  NpyArray array;
  array.shape = {static_cast<int64_t>(rows), static_cast<int64_t>(columns)};
  if (var->rank == 3) array.shape.push_back(static_cast<int64_t>(pages));
  array.values.resize(count);
  for (size_t r = 0; r < rows; ++r) {  // the file is column-major
    for (size_t c = 0; c < columns; ++c) {
      for (size_t p = 0; p < pages; ++p)
        array.values[(r * columns + c) * pages + p] = first[(p * columns + c) * rows + r];
    }
  }
  return array;
}

void WriteMatMatrix(const std::string& path, const std::string& variable, const NpyArray& array, bool v73) {
  InstallMatioLog();
  last_matio_message.clear();
  if (array.shape.size() != 2 && array.shape.size() != 3)
    throw std::invalid_argument("WriteMatMatrix: needs a 2-D or 3-D array");
  const auto rows = static_cast<size_t>(array.shape[0]);
  const auto columns = static_cast<size_t>(array.shape[1]);
  const auto pages = array.shape.size() == 3 ? static_cast<size_t>(array.shape[2]) : size_t{1};
  std::vector<double> column_major(rows * columns * pages);
  for (size_t r = 0; r < rows; ++r) {
    for (size_t c = 0; c < columns; ++c) {
      for (size_t p = 0; p < pages; ++p)
        column_major[(p * columns + c) * rows + r] = array.values[(r * columns + c) * pages + p];
    }
  }
  std::unique_ptr<mat_t, MatCloser> mat(
      Matio::Get().CreateVer(path.c_str(), nullptr, v73 ? MAT_FT_MAT73 : MAT_FT_MAT5));
  if (!mat) throw std::runtime_error(path + ": cannot create the .mat file" + MatioDetail());
  size_t dims[3] = {rows, columns, pages};
  std::unique_ptr<matvar_t, VarFreer> var(Matio::Get().VarCreate(variable.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE,
                                                                 static_cast<int>(array.shape.size()), dims,
                                                                 column_major.data(), MAT_F_DONT_COPY_DATA));
  if (!var || Matio::Get().VarWrite(mat.get(), var.get(), MAT_COMPRESSION_NONE) != 0) {
    throw std::runtime_error(path + ": cannot write variable '" + variable + "'" + MatioDetail());
  }
}

}  // namespace dream::formats
