#include "dream/workflows/script_export.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"
#include "dream/formats/sha256.h"
#include "dream/workflows/script_run_workflow.h"

namespace dream::workflows {

namespace fs = std::filesystem;

namespace {

/// A manifest bigger than this is no manifest dream export wrote.
constexpr size_t kMaxManifestBytes = 64 * 1024;

/// The checker's JSON line (the last line of its output). @throws naming the script.
nlohmann::json CheckerAnswer(const ScriptExport::Checked& checked, const std::string& script) {
  std::string output = checked.output;
  while (!output.empty() && output.back() == '\n') output.pop_back();
  if (checked.exit_code != 0) {
    throw std::runtime_error("dream export: " + script + ": cannot read its imports: " + output);
  }
  const nlohmann::json answer = nlohmann::json::parse(output.substr(output.rfind('\n') + 1), nullptr, false);
  if (!answer.is_object() || !answer.contains("imports") || !answer["imports"].is_array() ||
      !answer.contains("not_on_robotarium") || !answer["not_on_robotarium"].is_array()) {
    throw std::runtime_error("dream export: " + script +
                             ": the import checker said something else: " + output.substr(0, 300));
  }
  return answer;
}

/// DREAM's recorder with the script's file name in it (SCRIPT = "...").
std::string RecorderText(const std::string& python_runtime_dir, const std::string& script_file) {
  const std::string path = (fs::path(python_runtime_dir) / "rps_dream" / ScriptExport::kRecorderName).string();
  std::string text = files::ReadFileText(path);
  const std::string placeholder = "\"__DREAM_SCRIPT__\"";
  const size_t at = text.find(placeholder);
  if (at == std::string::npos) throw std::runtime_error(path + ": no " + placeholder + " to name the script in");
  // A JSON string of a file name is a Python string literal (ASCII escapes only).
  return text.replace(at, placeholder.size(), nlohmann::json(script_file).dump(-1, ' ', true));
}

std::string Joined(const nlohmann::json& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name.get<std::string>();
  return text;
}

}  // namespace

ScriptExport::Result ScriptExport::Export(const Options& options, const RunChecker& run_checker) const {
  std::error_code error;
  if (!fs::is_regular_file(options.script_path, error)) {
    throw std::runtime_error("dream export: " + options.script_path + ": no such script (a Python file)");
  }
  std::vector<std::string> argv = {options.python,
                                   (fs::path(options.python_runtime_dir) / "rps_dream" / "check_imports.py").string(),
                                   fs::absolute(options.script_path).string()};
  if (!options.libraries_path.empty()) argv.push_back(options.libraries_path);
  const nlohmann::json answer = CheckerAnswer(run_checker(argv), options.script_path);
  Result result;
  result.out_dir =
      options.out_dir.empty() ? "exports/" + ScriptRunWorkflow::RunName(options.script_path) : options.out_dir;
  result.script_file = fs::path(options.script_path).filename().string();
  result.main_file = kRecorderName;
  if (result.script_file == kRecorderName) {
    throw std::runtime_error("dream export: " + options.script_path + ": a script named " + kRecorderName +
                             " would take the place of DREAM's recorder in the upload; rename it");
  }
  for (const auto& name : answer["imports"]) result.imports.push_back(name.get<std::string>());
  if (!answer["not_on_robotarium"].empty()) {
    result.refused = true;
    result.refusal = options.script_path + " imports " + Joined(answer["not_on_robotarium"]) +
                     ", which the Robotarium does not have (it has Python's standard library, rps and " +
                     (options.libraries_path.empty() ? std::string("numpy, scipy, matplotlib, cvxopt")
                                                     : "the packages of " + options.libraries_path) +
                     ")";
    return result;
  }
  const std::string text = files::ReadFileText(options.script_path);
  const std::string recorder = RecorderText(options.python_runtime_dir, result.script_file);
  const fs::path upload = fs::path(result.out_dir) / "upload";
  fs::create_directories(upload, error);
  if (error) throw std::runtime_error("dream export: cannot create " + upload.string() + ": " + error.message());
  // Only this export's files in upload/: an earlier export's would be uploaded too.
  for (const auto& entry : fs::directory_iterator(upload)) {
    const std::string name = entry.path().filename().string();
    if (name != result.script_file && name != result.main_file) fs::remove_all(entry.path());
  }
  files::WriteFileAtomically((upload / result.script_file).string(), text);
  files::WriteFileAtomically((upload / result.main_file).string(), recorder);
  nlohmann::ordered_json manifest;
  manifest["script"] = fs::absolute(options.script_path).lexically_normal().string();
  manifest["main_file"] = result.main_file;
  manifest["sha256"] = formats::Sha256::Hex(recorder);
  manifest["script_file"] = result.script_file;
  manifest["script_sha256"] = formats::Sha256::Hex(text);
  manifest["imports"] = result.imports;
  manifest["checked_against"] = options.libraries_path.empty() ? "the official simulator's requirements (numpy, "
                                                                 "scipy, matplotlib, cvxopt) and the standard library"
                                                               : options.libraries_path;
  files::WriteFileAtomically((fs::path(result.out_dir) / kManifestName).string(), manifest.dump(2) + "\n");
  return result;
}

std::optional<ScriptExport::Manifest> ScriptExport::Read(const std::string& export_dir) {
  const std::string path = (fs::path(export_dir) / kManifestName).string();
  std::error_code error;
  if (!fs::exists(path, error)) return std::nullopt;
  const nlohmann::json json = nlohmann::json::parse(files::ReadFileText(path, kMaxManifestBytes), nullptr, false);
  Manifest manifest;
  for (auto [key, field] : {std::pair{"script", &manifest.script}, std::pair{"main_file", &manifest.main_file},
                            std::pair{"sha256", &manifest.sha256}}) {
    if (!json.is_object() || !json.contains(key) || !json[key].is_string()) {
      throw std::runtime_error(path + ": " + key + " is missing or not text: not a manifest dream export wrote");
    }
    *field = json[key].get<std::string>();
  }
  for (auto [key, field] :
       {std::pair{"script_file", &manifest.script_file}, std::pair{"script_sha256", &manifest.script_sha256}}) {
    if (json.contains(key) && json[key].is_string()) *field = json[key].get<std::string>();
  }
  if (!manifest.script_file.empty() && fs::path(manifest.script_file).filename().string() != manifest.script_file) {
    throw std::runtime_error(path + ": script_file '" + manifest.script_file + "' is no file name");
  }
  if (manifest.main_file.empty() || fs::path(manifest.main_file).filename().string() != manifest.main_file) {
    throw std::runtime_error(path + ": main_file '" + manifest.main_file + "' is no file name");
  }
  return manifest;
}

}  // namespace dream::workflows
