#include "dream/view/video_export_request.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "dream/robotarium/robotarium_constants.h"

namespace dream::view {
namespace {

constexpr size_t kMaxParameters = 24;
constexpr size_t kMaxValueChars = 24;

using Invalid = VideoExportRequest::Invalid;

std::string Quoted(const std::string& name, const std::string& value) { return name + "=" + value; }

double Number(const std::string& name, const std::string& value, double min, double max) {
  double number = 0.0;
  size_t used = 0;
  try {
    number = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  // Decimal only: stod would take "0x10" and "inf".
  const bool decimal = std::all_of(value.begin(), value.end(), [](char c) {
    return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E';
  });
  if (value.empty() || !decimal || used != value.size() || !std::isfinite(number)) {
    throw Invalid(Quoted(name, value) + ": not a number");
  }
  if (number < min || number > max) {
    char range[64];
    std::snprintf(range, sizeof(range), "%g..%g", min, max);
    throw Invalid(Quoted(name, value) + ": out of bounds " + range);
  }
  return number;
}

int64_t Step(const std::string& name, const std::string& value) {
  if (value.empty() || value.size() > 12 ||
      !std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    throw Invalid(Quoted(name, value) + ": not a step (a whole number >= 0)");
  }
  return std::stoll(value);
}

bool Flag(const std::string& name, const std::string& value) {
  if (value == "1") return true;
  if (value == "0") return false;
  throw Invalid(Quoted(name, value) + ": expected 0 or 1");
}

// name=value pairs, each name once, every name known.
std::map<std::string, std::string> Pairs(std::string_view query) {
  static const std::set<std::string> kKnown = {"format",     "width", "fps",   "speed",   "trail",   "x0",
                                               "y0",         "x1",    "y1",    "from",    "to",      "goals",
                                               "violations", "ids",   "radio", "sensors", "drawings"};
  std::map<std::string, std::string> pairs;
  size_t at = 0;
  while (at < query.size()) {
    const size_t end = std::min(query.find('&', at), query.size());
    const std::string_view pair = query.substr(at, end - at);
    at = end + 1;
    if (pair.empty()) continue;
    if (pairs.size() >= kMaxParameters) throw Invalid("more than " + std::to_string(kMaxParameters) + " parameters");
    const size_t equals = pair.find('=');
    const std::string name(pair.substr(0, std::min(equals, pair.size())).substr(0, 32));
    if (equals == std::string_view::npos) throw Invalid(name + ": no value (name=value)");
    const std::string value(pair.substr(equals + 1));
    if (kKnown.count(name) == 0) throw Invalid(name + ": not a parameter of /export/start");
    if (value.size() > kMaxValueChars)
      throw Invalid(name + ": value over " + std::to_string(kMaxValueChars) + " chars");
    if (!pairs.emplace(name, value).second) throw Invalid(name + ": given twice");
  }
  return pairs;
}

// Six significant digits: what the printed command says, and so what is drawn.
std::string Text(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", value);
  return text;
}

}  // namespace

VideoExportRequest VideoExportRequest::Parse(std::string_view query, const world::Arena& arena, int64_t run_first_step,
                                             int64_t run_last_step) {
  const std::map<std::string, std::string> pairs = Pairs(query);
  auto has = [&](const char* name) { return pairs.count(name) > 0; };
  VideoExportRequest request;
  if (has("format")) {
    const std::string& format = pairs.at("format");
    if (format != "mp4" && format != "gif") throw Invalid(Quoted("format", format) + ": expected mp4 or gif");
    request.gif = format == "gif";
  }
  if (request.gif) {
    request.width_px = 480;
    request.fps = 15;
  }
  if (has("width")) {
    const double width = Number("width", pairs.at("width"), kMinWidthPx, kMaxWidthPx);
    if (width != std::floor(width)) throw Invalid(Quoted("width", pairs.at("width")) + ": not a whole number of px");
    request.width_px = static_cast<int>(width);
  }
  if (has("fps")) request.fps = Number("fps", pairs.at("fps"), 1, kMaxFps);
  if (has("speed")) request.speed = Number("speed", pairs.at("speed"), kMinSpeed, kMaxSpeed);
  if (has("trail")) request.trail_s = Number("trail", pairs.at("trail"), 0, kMaxTrailS);
  const int corners = has("x0") + has("y0") + has("x1") + has("y1");
  if (corners != 0 && corners != 4) throw Invalid("x0, y0, x1, y1: give all four (the viewport) or none");
  if (corners == 4) {
    const double bound = 1000.0;  // checked closely below, against the arena
    render::Viewport viewport{Number("x0", pairs.at("x0"), -bound, bound), Number("y0", pairs.at("y0"), -bound, bound),
                              Number("x1", pairs.at("x1"), -bound, bound), Number("y1", pairs.at("y1"), -bound, bound)};
    try {
      viewport.Check(arena, "x0,y0,x1,y1");
    } catch (const std::invalid_argument& e) {
      throw Invalid(e.what());
    }
    request.viewport = viewport;
  }
  if (has("from") != has("to")) throw Invalid("from, to: give both (the steps) or neither");
  if (has("from")) {
    request.first_step = Step("from", pairs.at("from"));
    request.last_step = Step("to", pairs.at("to"));
    const std::string range = "from=" + pairs.at("from") + "&to=" + pairs.at("to");
    if (request.first_step > request.last_step) throw Invalid(range + ": from is after to");
    if (request.first_step < run_first_step || request.last_step > run_last_step) {
      throw Invalid(range + ": not in the run (steps " + std::to_string(run_first_step) + "-" +
                    std::to_string(run_last_step) + ")");
    }
  }
  // As the command the page prints gives them: the export is that command's video.
  request.fps = std::stod(Text(request.fps));
  request.speed = std::stod(Text(request.speed));
  request.trail_s = std::stod(Text(request.trail_s));
  if (request.viewport) request.viewport = render::Viewport::Parse(request.viewport->Text(), arena);
  if (has("goals")) request.goals = Flag("goals", pairs.at("goals"));
  if (has("violations")) request.violations = Flag("violations", pairs.at("violations"));
  if (has("ids")) request.robot_ids = Flag("ids", pairs.at("ids"));
  if (has("drawings")) request.drawings = Flag("drawings", pairs.at("drawings"));
  if (has("radio")) request.radio_links = Flag("radio", pairs.at("radio"));
  if (has("sensors")) request.sensor_ranges = Flag("sensors", pairs.at("sensors"));
  const int64_t frames = request.FrameCount(run_first_step, run_last_step);
  if (frames > kMaxFrames) {
    throw Invalid("speed=" + Text(request.speed) + "&fps=" + Text(request.fps) + ": " + std::to_string(frames) +
                  " frames, over " + std::to_string(kMaxFrames) + " (a higher speed, fewer fps or fewer steps)");
  }
  return request;
}

int64_t VideoExportRequest::FrameCount(int64_t run_first_step, int64_t run_last_step) const {
  const int64_t first = first_step >= 0 ? first_step : run_first_step;
  const int64_t last = last_step >= 0 ? last_step : run_last_step;
  const double shown_s =
      static_cast<double>(std::max<int64_t>(0, last - first)) * robotarium::RobotariumConstants::kTimeStepSeconds;
  // As RunAnimation counts them: the run's frames, then its end held 1 s.
  return static_cast<int64_t>(std::ceil(shown_s * fps / speed - 1e-9)) + 1 + std::lround(fps);
}

std::vector<std::string> VideoExportRequest::RenderArguments() const {
  std::vector<std::string> args = {
      "--width", std::to_string(width_px), "--fps", Text(fps), "--speed", Text(speed), "--trail", Text(trail_s)};
  // One word: a value that starts with '-' is not taken for an option by any reader of the command.
  if (viewport) args.push_back("--viewport=" + viewport->Text());
  if (first_step >= 0)
    args.insert(args.end(), {"--steps", std::to_string(first_step) + "-" + std::to_string(last_step)});
  if (!goals) args.emplace_back("--no-goals");
  if (!violations) args.emplace_back("--no-violations");
  if (!robot_ids) args.emplace_back("--no-ids");
  if (!drawings) args.emplace_back("--no-drawings");
  if (radio_links) args.emplace_back("--radio-links");
  if (sensor_ranges) args.emplace_back("--sensor-ranges");
  return args;
}

}  // namespace dream::view
