#include "dream/formats/npz_file.h"

#include <fcntl.h>
#include <unistd.h>
#include <zip.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "dream/files/regular_file.h"

namespace dream::formats {
namespace {

zip_t* Archive(void* archive) { return static_cast<zip_t*>(archive); }

// The most members whose names we list: an archive's count is its own claim.
constexpr zip_int64_t kMaxListedMembers = 1000;

}  // namespace

NpzFile::NpzFile(std::string path) : path_(std::move(path)) {
  // Opened without blocking (a FIFO or device is refused), then handed to
  // libzip by descriptor: it reads the very file that was checked.
  const files::RegularFile file(path_);
  const int fd = ::fcntl(file.descriptor(), F_DUPFD_CLOEXEC, 0);
  if (fd < 0) throw std::runtime_error(path_ + ": cannot read the file: " + std::strerror(errno));
  int error = 0;
  archive_ = zip_fdopen(fd, ZIP_CHECKCONS, &error);  // on success libzip owns (and closes) fd
  if (archive_ == nullptr) {
    ::close(fd);
    zip_error_t reason;
    zip_error_init_with_code(&reason, error);
    const std::string text = zip_error_strerror(&reason);
    zip_error_fini(&reason);
    throw std::runtime_error(path_ + ": not a readable .npz (zip) file: " + text);
  }
}

NpzFile::~NpzFile() {
  if (archive_ != nullptr) zip_discard(Archive(archive_));
}

std::optional<NpyArray> NpzFile::Read(const std::string& name, int64_t max_bytes) const {
  const std::string member = name + ".npy";
  const zip_int64_t index = zip_name_locate(Archive(archive_), member.c_str(), 0);
  if (index < 0) return std::nullopt;
  const std::string where = path_ + ": member " + member;
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat_index(Archive(archive_), static_cast<zip_uint64_t>(index), 0, &stat) != 0 ||
      (stat.valid & ZIP_STAT_SIZE) == 0) {
    throw std::runtime_error(where + ": its size cannot be read (damaged?)");
  }
  if (stat.size > static_cast<zip_uint64_t>(max_bytes)) {
    throw std::runtime_error(where + " declares " + std::to_string(stat.size) + " bytes, more than the " +
                             std::to_string(max_bytes) + " an array may have here");
  }
  zip_file_t* file = zip_fopen_index(Archive(archive_), static_cast<zip_uint64_t>(index), 0);
  if (file == nullptr) {
    throw std::runtime_error(where + ": cannot be opened: " + zip_strerror(Archive(archive_)));
  }
  std::string bytes(static_cast<size_t>(stat.size), '\0');
  const zip_int64_t got = bytes.empty() ? 0 : zip_fread(file, bytes.data(), stat.size);
  char extra = 0;
  const zip_int64_t more = zip_fread(file, &extra, 1);  // 0 at the end; -1 on a CRC mismatch
  const std::string problem = zip_file_strerror(file);
  zip_fclose(file);
  if (got != static_cast<zip_int64_t>(stat.size) || more != 0) {
    throw std::runtime_error(where + ": does not inflate to the " + std::to_string(stat.size) +
                             " bytes it declares, or fails its CRC (damaged or cut short?): " + problem);
  }
  return DecodeNpy(bytes, where);
}

std::vector<std::string> NpzFile::Names() const {
  std::vector<std::string> names;
  const zip_int64_t count = zip_get_num_entries(Archive(archive_), 0);
  for (zip_int64_t i = 0; i < count && i < kMaxListedMembers; ++i) {
    const char* member = zip_get_name(Archive(archive_), static_cast<zip_uint64_t>(i), 0);
    if (member == nullptr) continue;
    std::string text = member;
    if (text.size() > 4 && text.compare(text.size() - 4, 4, ".npy") == 0) text.resize(text.size() - 4);
    names.push_back(text);
  }
  return names;
}

}  // namespace dream::formats
