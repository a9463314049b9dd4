#include "dream/bridge/flat_python_runtime.h"

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "dream/files/file_text.h"

namespace dream::bridge {
namespace {

namespace fs = std::filesystem;

const std::regex kRelativeImport(R"(^(\s*)from\s+\.([A-Za-z_][A-Za-z_0-9]*)\s+import\s+(.*)$)");
// Any other way of reaching the package or a sibling: `from . import X`, `from ..X`, `import dream.X`.
const std::regex kOtherPackageImport(R"(^\s*(from\s+\.|import\s+dream\b|from\s+dream\b))");
const std::regex kImportStatement(R"(^\s*import\s+([A-Za-z_][\w.]*(\s*,\s*[A-Za-z_][\w.]*)*))");
const std::regex kFromStatement(R"(^\s*from\s+([A-Za-z_]\w*))");

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

/// The top-level module names `text` imports (`import a.b, c` -> a, c; `from x.y import z` -> x).
void AddImportedNames(const std::string& text, std::set<std::string>* names) {
  for (const std::string& line : Lines(text)) {
    std::smatch match;
    if (std::regex_search(line, match, kImportStatement)) {
      std::istringstream list(match[1].str());
      std::string item;
      while (std::getline(list, item, ',')) {
        item.erase(0, item.find_first_not_of(" \t"));
        names->insert(item.substr(0, item.find_first_of(". \t")));
      }
    } else if (std::regex_search(line, match, kFromStatement)) {
      names->insert(match[1].str());
    }
  }
}

bool IsPythonKeyword(const std::string& word) {
  static const std::set<std::string> kKeywords = {
      "False", "None",     "True",  "and",    "as",   "assert", "async",  "await",    "break",
      "class", "continue", "def",   "del",    "elif", "else",   "except", "finally",  "for",
      "from",  "global",   "if",    "import", "in",   "is",     "lambda", "nonlocal", "not",
      "or",    "pass",     "raise", "return", "try",  "while",  "with",   "yield"};
  return kKeywords.count(word) != 0;
}

bool IsIdentifier(const std::string& text) {
  static const std::regex kIdentifier("[A-Za-z_][A-Za-z_0-9]*");
  return std::regex_match(text, kIdentifier);
}

}  // namespace

const std::vector<std::string>& FlatPythonRuntime::ShippedModules() {
  // robot_agent and controller_spec drive the controller; the others are what
  // they and a controller import (drawing: Robot's draw_*, which the lab's
  // runner leaves undrawn). Never lcm, agent_host, embedded: the
  // LCM transport and hosting, which the script replaces.
  static const std::vector<std::string> kModules = {"motion",      "drawing",  "robot",          "sensors",
                                                    "radios",      "timer",    "robot_agent",    "controller_spec",
                                                    "hrvo",        "barriers", "toolbox_checks", "transformations",
                                                    "controllers", "graph",    "misc",           "__init__"};
  return kModules;
}

std::string FlatPythonRuntime::FileNameOf(const std::string& module) {
  return module == "__init__" ? "dream.py" : "dream_" + module + ".py";
}

std::string FlatPythonRuntime::Flatten(const std::string& module, const std::string& text, const std::string& path) {
  (void)module;
  const std::vector<std::string>& shipped = ShippedModules();
  std::string out;
  out.reserve(text.size() + 256);
  const std::vector<std::string> lines = Lines(text);
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const std::string where = path + ":" + std::to_string(i + 1) + ": ";
    std::smatch match;
    if (std::regex_match(line, match, kRelativeImport)) {
      const std::string target = match[2].str();
      const std::string names = match[3].str();
      if (std::find(shipped.begin(), shipped.end(), target) == shipped.end() || target == "__init__") {
        std::string listed;
        for (const std::string& name : shipped) {
          if (name != "__init__") listed += (listed.empty() ? "" : ", ") + name;
        }
        throw std::runtime_error(where + "imports ." + target +
                                 ", which a Robotarium submission does not ship (it ships " + listed + ")");
      }
      const bool opens = names.find('(') != std::string::npos && names.find(')') == std::string::npos;
      if (opens || (!names.empty() && names.back() == '\\')) {
        throw std::runtime_error(where +
                                 "a relative import spans lines; the flat-file rule wants one line, "
                                 "`from ." +
                                 target + " import a, b` (docs/python-runtime-contract.md)");
      }
      out += match[1].str() + "from " + FileNameOf(target).substr(0, FileNameOf(target).size() - 3) + " import " +
             names + "\n";
      continue;
    }
    if (std::regex_search(line, kOtherPackageImport)) {
      throw std::runtime_error(where + "'" + line +
                               "': inside the package only single-line `from .X import a, b` "
                               "imports work in a Robotarium submission's flat files "
                               "(docs/python-runtime-contract.md)");
    }
    out += line + "\n";
  }
  return out;
}

FlatPythonRuntime FlatPythonRuntime::Read(const std::string& runtime_dir) {
  const fs::path package = fs::path(runtime_dir) / "dream";
  FlatPythonRuntime runtime;
  for (const std::string& module : ShippedModules()) {
    const std::string path = (package / (module + ".py")).string();
    if (!fs::is_regular_file(path)) {
      throw std::runtime_error(path + ": missing; the controller strategy ships the Python runtime from " +
                               package.string() + " (is this dream's python/ folder complete?)");
    }
    runtime.files_.push_back({FileNameOf(module), Flatten(module, files::ReadFileText(path), path)});
  }
  return runtime;
}

std::set<std::string> FlatPythonRuntime::ImportedModules(const std::vector<std::string>& more_sources) const {
  std::set<std::string> names;
  for (const File& file : files_) AddImportedNames(file.text, &names);
  for (const std::string& source : more_sources) AddImportedNames(source, &names);
  return names;
}

std::string FlatPythonRuntime::ControllerFileName(const std::string& module_path, const std::string& module_text,
                                                  const std::set<std::string>& taken, const std::string& config_file) {
  const fs::path path(module_path);
  const std::string name = path.filename().string();
  const std::string stem = path.stem().string();
  auto refuse = [&](const std::string& problem) {
    throw std::runtime_error(config_file + ": controller.module: '" + module_path + "': " + problem);
  };
  if (path.extension() != ".py" || !IsIdentifier(stem) || IsPythonKeyword(stem)) {
    refuse("'" + name +
           "' is not an importable module file name (letters, digits and _, not a Python keyword, "
           "ending in .py); rename the file");
  }
  if (stem == "dream" || stem.rfind("dream_", 0) == 0) {
    refuse("'" + name + "' would clash with the submission's own files (dream.py, dream_*.py); rename the module");
  }
  if (taken.count(stem) != 0) {
    refuse("'" + name + "' would hide the module '" + stem +
           "' that the submission script or the runtime imports; "
           "rename the module");
  }
  std::set<std::string> imported;
  AddImportedNames(module_text, &imported);
  for (const std::string& line : Lines(module_text)) {
    if (std::regex_search(line, std::regex(R"(^\s*from\s+\.)"))) {
      refuse("it imports relatively ('" + line + "'); a submission holds the module alone, not its package");
    }
  }
  const fs::path folder = path.parent_path();
  for (const std::string& helper : imported) {
    if (helper == "dream") continue;  // the runtime, shipped as dream.py
    std::error_code error;
    if (fs::is_regular_file(folder / (helper + ".py"), error) || fs::is_directory(folder / helper, error)) {
      refuse("it imports '" + helper +
             "', which sits beside it; a submission ships the controller module alone — "
             "put what it needs into the module");
    }
  }
  return name;
}

}  // namespace dream::bridge
