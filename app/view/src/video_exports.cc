#include "dream/view/video_exports.h"

#include <spdlog/spdlog.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "json_writer.h"

namespace dream::view {
namespace {

namespace fs = std::filesystem;

// A folder of its own for one export (mkdtemp: exclusive, unguessable), gone with it.
class PrivateFolder {
 public:
  PrivateFolder() {
    std::string pattern = (fs::temp_directory_path() / "dream-view-export-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      throw std::runtime_error("cannot make a temporary folder in " + fs::temp_directory_path().string());
    }
    path_ = pattern;
  }
  ~PrivateFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  PrivateFolder(const PrivateFolder&) = delete;
  PrivateFolder& operator=(const PrivateFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::shared_ptr<const std::string> ReadVideo(const fs::path& path) {
  const auto bytes = static_cast<int64_t>(fs::file_size(path));
  if (bytes > VideoExports::kMaxVideoBytes) {
    throw std::runtime_error("the video has " + std::to_string(bytes >> 20) + " MiB, over the " +
                             std::to_string(VideoExports::kMaxVideoBytes >> 20) +
                             " MiB the view holds: a smaller width, fewer fps or fewer steps (or dream render)");
  }
  std::ifstream in(path, std::ios::binary);
  auto video = std::make_shared<std::string>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw std::runtime_error("cannot read back " + path.string());
  return video;
}

std::string Joined(const std::string& start, const std::vector<std::string>& args) {
  std::string text = start;
  for (const std::string& arg : args) text += " " + arg;
  return text;
}

}  // namespace

VideoExports::VideoExports(Run run, Render render) : run_(std::move(run)), render_(std::move(render)) {}

VideoExports::~VideoExports() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

std::string VideoExports::FileName(const VideoExportRequest& request) const {
  std::string name;
  for (const char c : run_.name.substr(0, 64)) {
    const bool safe =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    name += safe ? c : '_';
  }
  if (name.empty() || name.front() == '.') name = "run" + name;
  const int64_t first = request.first_step >= 0 ? request.first_step : run_.first_step;
  const int64_t last = request.last_step >= 0 ? request.last_step : run_.last_step;
  return name + "_steps_" + std::to_string(first) + "-" + std::to_string(last) + "." + request.Extension();
}

VideoExports::Answer VideoExports::Start(std::string_view query) {
  VideoExportRequest request;
  try {
    request = VideoExportRequest::Parse(query, run_.arena, run_.first_step, run_.last_step);
  } catch (const std::invalid_argument& e) {
    std::string json;
    JsonWriter(&json).BeginObject().Key("error").String(e.what()).EndObject();
    return {400, json};
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (state_ == State::kRunning) {
    std::string json;
    JsonWriter(&json)
        .BeginObject()
        .Key("error")
        .String("busy: export " + std::to_string(job_) + " is being drawn (" + std::to_string(drawn_) + " of " +
                std::to_string(total_) + " frames); one at a time")
        .EndObject();
    return {409, json};
  }
  if (thread_.joinable()) thread_.join();  // the last one is over: its thread ends at once
  const std::string file_name = FileName(request);
  state_ = State::kRunning;
  ++job_;
  drawn_ = 0;
  total_ = static_cast<int>(request.FrameCount(run_.first_step, run_.last_step));
  error_.clear();
  command_ = Joined(run_.render_command + " --out " + file_name, request.RenderArguments());
  video_ = {};
  thread_ = std::thread([this, request, file_name] { Draw(request, file_name); });
  return {202, StatusJsonLocked()};
}

void VideoExports::Draw(VideoExportRequest request, std::string file_name) {
  std::shared_ptr<const std::string> bytes;
  std::string error;
  try {
    const PrivateFolder folder;
    const fs::path out = folder.path() / file_name;
    render_(
        request, out.string(),
        [this](int drawn, int total) {
          std::lock_guard<std::mutex> lock(mutex_);
          drawn_ = drawn;
          total_ = total;
        },
        stop_);
    if (stop_.load()) return;
    bytes = ReadVideo(out);
  } catch (const std::exception& e) {
    error = e.what();
    spdlog::warn("dream view: export failed: {}", error);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (bytes) {
    state_ = State::kDone;
    video_ = {bytes, file_name};
  } else {
    state_ = State::kFailed;
    error_ = error.empty() ? "the video was not written" : error;
  }
}

std::string VideoExports::StatusJson() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return StatusJsonLocked();
}

std::string VideoExports::StatusJsonLocked() const {
  static constexpr const char* kStates[] = {"idle", "running", "done", "failed"};
  std::string json;
  JsonWriter out(&json);
  out.BeginObject().Key("state").String(kStates[static_cast<int>(state_)]).Key("job").Integer(job_);
  out.Key("drawn").Integer(drawn_).Key("total").Integer(total_);
  if (!error_.empty()) out.Key("error").String(error_);
  if (video_.bytes) {
    out.Key("file").String(video_.file_name).Key("bytes").Integer(static_cast<int64_t>(video_.bytes->size()));
  }
  if (!command_.empty()) out.Key("command").String(command_);
  out.EndObject();
  return json;
}

VideoExports::Video VideoExports::Finished() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_ == State::kDone ? video_ : Video{};
}

}  // namespace dream::view
