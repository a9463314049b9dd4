#include "dream/formats/npy_file.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "dream/files/regular_file.h"

namespace dream::formats {
namespace {

static_assert(sizeof(double) == 8 && std::numeric_limits<double>::is_iec559, "the .npy code needs IEEE doubles");
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "the .npy code writes '<f8' by copying memory: it needs a little-endian machine"
#endif

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicSize = 6;
constexpr int64_t kMaxDimensions = 8;

[[noreturn]] void Fail(const std::string& name, const std::string& problem) {
  throw std::runtime_error(name + ": " + problem);
}

/// The header dict, e.g. {'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }
class HeaderParser {
 public:
  HeaderParser(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  void Parse(std::string* descr, bool* fortran_order, std::vector<int64_t>* shape) {
    bool have_descr = false;
    bool have_order = false;
    bool have_shape = false;
    Expect('{');
    while (true) {
      SkipSpaces();
      if (Peek() == '}') {
        ++pos_;
        break;
      }
      const std::string key = QuotedString();
      Expect(':');
      if (key == "descr") {
        if (have_descr) Bad("repeats the key 'descr'");
        *descr = QuotedString();
        have_descr = true;
      } else if (key == "fortran_order") {
        if (have_order) Bad("repeats the key 'fortran_order'");
        *fortran_order = Boolean();
        have_order = true;
      } else if (key == "shape") {
        if (have_shape) Bad("repeats the key 'shape'");
        *shape = Shape();
        have_shape = true;
      } else {
        Bad("has an unexpected key '" + key + "'");
      }
      SkipSpaces();
      if (Peek() == ',') {
        ++pos_;
      } else if (Peek() != '}') {
        Bad("expected ',' or '}' at header byte " + std::to_string(pos_));
      }
    }
    SkipSpaces();
    if (pos_ != text_.size()) Bad("has text after the closing '}'");
    if (!have_descr || !have_order || !have_shape) Bad("lacks one of the keys descr, fortran_order, shape");
  }

 private:
  [[noreturn]] void Bad(const std::string& problem) const { Fail(name_, "not a valid .npy header: it " + problem); }
  char Peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }
  void SkipSpaces() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n')) ++pos_;
  }
  void Expect(char c) {
    SkipSpaces();
    if (Peek() != c) Bad(std::string("expected '") + c + "' at header byte " + std::to_string(pos_));
    ++pos_;
  }
  std::string QuotedString() {
    SkipSpaces();
    const char quote = Peek();
    if (quote != '\'' && quote != '"') Bad("expected a quoted string at header byte " + std::to_string(pos_));
    const size_t end = text_.find(quote, pos_ + 1);
    if (end == std::string::npos || end - pos_ > 64) Bad("has an unterminated or overlong string");
    std::string value = text_.substr(pos_ + 1, end - pos_ - 1);
    pos_ = end + 1;
    return value;
  }
  bool Boolean() {
    SkipSpaces();
    if (text_.compare(pos_, 4, "True") == 0) {
      pos_ += 4;
      return true;
    }
    if (text_.compare(pos_, 5, "False") == 0) {
      pos_ += 5;
      return false;
    }
    Bad("expected True or False for fortran_order");
  }
  std::vector<int64_t> Shape() {
    std::vector<int64_t> shape;
    Expect('(');
    while (true) {
      SkipSpaces();
      if (Peek() == ')') {
        ++pos_;
        return shape;
      }
      if (!std::isdigit(static_cast<unsigned char>(Peek()))) Bad("has a shape that is not a tuple of whole numbers");
      int64_t value = 0;
      while (std::isdigit(static_cast<unsigned char>(Peek()))) {
        if (value > (std::numeric_limits<int64_t>::max() - 9) / 10) Bad("has an absurdly large dimension");
        value = value * 10 + (Peek() - '0');
        ++pos_;
      }
      shape.push_back(value);
      if (static_cast<int64_t>(shape.size()) > kMaxDimensions) Bad("has more than 8 dimensions");
      SkipSpaces();
      if (Peek() == ',') {
        ++pos_;
      } else if (Peek() != ')') {
        Bad("has a malformed shape tuple");
      }
    }
  }

  const std::string& text_;
  const std::string& name_;
  size_t pos_ = 0;
};

// The values of a Fortran-order array of `shape` in C order (the last index fastest).
std::vector<double> COrderOfFortran(const std::vector<double>& fortran, const std::vector<int64_t>& shape) {
  std::vector<double> c_order(fortran.size());
  std::vector<int64_t> index(shape.size(), 0);
  for (size_t c = 0; c < c_order.size(); ++c) {
    int64_t at = 0;  // the Fortran position of `index`
    for (size_t d = shape.size(); d-- > 0;) at = at * shape[d] + index[d];
    c_order[c] = fortran[static_cast<size_t>(at)];
    for (size_t d = shape.size(); d-- > 0;) {  // the next index in C order
      if (++index[d] < shape[d]) break;
      index[d] = 0;
    }
  }
  return c_order;
}

}  // namespace

int64_t NpyArray::size() const {
  int64_t count = 1;
  for (int64_t d : shape) count *= d;
  return count;
}

namespace {

/// Magic, version 1.0 and the header dict for `descr` and `shape`, padded so the data starts at a multiple of 64.
std::string NpyHeader(const char* descr, const std::vector<int64_t>& dims) {
  std::string shape = "(";
  for (size_t i = 0; i < dims.size(); ++i) {
    shape += std::to_string(dims[i]);
    if (dims.size() == 1 || i + 1 < dims.size()) shape += ",";
    if (i + 1 < dims.size()) shape += " ";
  }
  shape += ")";
  std::string header = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
  // magic + version + 2-byte length + header + '\n', padded with spaces to a multiple of 64.
  const size_t unpadded = kMagicSize + 2 + 2 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  if (header.size() > 65535) throw std::invalid_argument("EncodeNpy: header too long");
  std::string bytes(kMagic, kMagicSize);
  bytes += '\x01';
  bytes += '\x00';
  bytes += static_cast<char>(header.size() & 0xff);
  bytes += static_cast<char>((header.size() >> 8) & 0xff);
  bytes += header;
  return bytes;
}

}  // namespace

std::string EncodeNpy(const NpyArray& array) {
  for (int64_t d : array.shape) {
    if (d < 0) throw std::invalid_argument("EncodeNpy: negative dimension");
  }
  if (array.size() != static_cast<int64_t>(array.values.size())) {
    throw std::invalid_argument("EncodeNpy: shape holds " + std::to_string(array.size()) + " values, got " +
                                std::to_string(array.values.size()));
  }
  std::string bytes = NpyHeader("<f8", array.shape);
  const size_t data_offset = bytes.size();
  bytes.resize(data_offset + array.values.size() * 8);
  if (!array.values.empty()) std::memcpy(&bytes[data_offset], array.values.data(), array.values.size() * 8);
  return bytes;
}

std::string EncodeNpyBytes(const std::string& bytes) {
  std::string file = NpyHeader("|u1", {static_cast<int64_t>(bytes.size())});
  return file + bytes;
}

NpyArray DecodeNpy(const std::string& bytes, const std::string& name) {
  if (bytes.size() < kMagicSize + 4 || bytes.compare(0, kMagicSize, kMagic, kMagicSize) != 0) {
    Fail(name, "not a .npy file (it does not start with \\x93NUMPY)");
  }
  const auto major = static_cast<unsigned char>(bytes[6]);
  const auto minor = static_cast<unsigned char>(bytes[7]);
  size_t header_length = 0;
  size_t header_start = 0;
  if (major == 1 && minor == 0) {
    header_length =
        static_cast<unsigned char>(bytes[8]) | (static_cast<size_t>(static_cast<unsigned char>(bytes[9])) << 8);
    header_start = 10;
  } else if ((major == 2 || major == 3) && minor == 0) {
    if (bytes.size() < 12) Fail(name, "cut short inside the .npy header");
    for (int i = 3; i >= 0; --i) header_length = (header_length << 8) | static_cast<unsigned char>(bytes[8 + i]);
    header_start = 12;
  } else {
    Fail(name, ".npy format version " + std::to_string(major) + "." + std::to_string(minor) + " is not supported");
  }
  if (header_length > 1 << 20) {
    Fail(name,
         "the .npy header length field says " + std::to_string(header_length) + " bytes; numpy writes a few hundred");
  }
  if (bytes.size() < header_start + header_length) {
    Fail(name, "cut short inside the .npy header: its length field says " + std::to_string(header_length) + " bytes, " +
                   std::to_string(bytes.size() - header_start) + " follow");
  }
  std::string header = bytes.substr(header_start, header_length);
  while (!header.empty() && (header.back() == '\n' || header.back() == ' ')) header.pop_back();
  std::string descr;
  bool fortran_order = false;
  NpyArray array;
  HeaderParser(header, name).Parse(&descr, &fortran_order, &array.shape);
  if (descr != "<f8") {
    Fail(name,
         "holds dtype '" + descr + "'; expected float64 ('<f8'); save it with np.save(name, array.astype(np.float64))");
  }
  int64_t count = 1;
  std::string shape_text;
  for (int64_t d : array.shape) shape_text += (shape_text.empty() ? "" : ", ") + std::to_string(d);
  for (int64_t d : array.shape) {
    if (d != 0 && count > std::numeric_limits<int64_t>::max() / 8 / d)
      Fail(name, "has an absurd shape (" + shape_text + ")");
    count *= d;
  }
  const size_t data_start = header_start + header_length;
  const auto expected = static_cast<uint64_t>(count) * 8;
  const uint64_t actual = bytes.size() - data_start;
  if (actual < expected) {
    Fail(name, "is cut short: its shape (" + shape_text + ") needs " + std::to_string(expected) +
                   " bytes of data, it has " + std::to_string(actual));
  }
  if (actual > expected) {
    Fail(name,
         "has " + std::to_string(actual - expected) + " bytes after the data its shape (" + shape_text + ") describes");
  }
  array.values.resize(static_cast<size_t>(count));
  if (count > 0) std::memcpy(array.values.data(), bytes.data() + data_start, static_cast<size_t>(expected));
  // Fortran order (what scipy.io.loadmat and MATLAB give; numpy saves it so):
  // the first index runs fastest. NpyArray is always C order.
  if (fortran_order && array.shape.size() > 1) array.values = COrderOfFortran(array.values, array.shape);
  return array;
}

NpyArray ReadNpyFile(const std::string& path, int64_t max_bytes) {
  files::RegularFile file(path);  // a FIFO or device is refused, not waited on
  if (file.size() > static_cast<std::uintmax_t>(max_bytes)) {
    throw std::runtime_error(path + ": " + std::to_string(file.size()) + " bytes is larger than any result of a " +
                             "Robotarium run (" + std::to_string(max_bytes) + " bytes); is it the right file?");
  }
  return DecodeNpy(file.ReadAll(static_cast<std::uintmax_t>(max_bytes)), path);
}

}  // namespace dream::formats
