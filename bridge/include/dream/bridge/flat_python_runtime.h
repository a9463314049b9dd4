#pragma once

#include <set>
#include <string>
#include <vector>

namespace dream::bridge {

/// The Python controller runtime (python/dream/) as the flat files a
/// Robotarium submission may hold (the lab takes files, no folders), by the
/// contract's flat-file rule (docs/python-runtime-contract.md): dream/X.py
/// becomes dream_X.py, dream/__init__.py becomes dream.py, and each
/// single-line relative import `from .X import a, b` becomes
/// `from dream_X import a, b`. Only the modules a submission needs are
/// shipped (kShippedModules); the LCM transport and hosting stay at home.
class FlatPythonRuntime {
 public:
  struct File {
    std::string name;  ///< file name in the submission, e.g. dream_robot.py
    std::string text;
  };

  /// The package's modules a submission ships, by module name.
  static const std::vector<std::string>& ShippedModules();

  /// Reads and flattens every shipped module of `runtime_dir`/dream/.
  /// @throws std::runtime_error naming the file: missing, or an import the
  ///         flat layout cannot follow (see Flatten).
  static FlatPythonRuntime Read(const std::string& runtime_dir);

  /// `text` of the module `module` (file `path`, for messages) with its
  /// relative imports rewritten. @throws std::runtime_error "<path>:<line>:
  /// ..." for an import of the package that is not a single-line
  /// `from .X import ...` of a shipped module (`from . import X`,
  /// `import dream.X`, `from .X import (` spanning lines, an unshipped X).
  static std::string Flatten(const std::string& module, const std::string& text, const std::string& path);

  /// The submission's file name of the module `module`: dream_X.py, dream.py for __init__.
  static std::string FileNameOf(const std::string& module);

  /// The shipped files, in ShippedModules() order.
  const std::vector<File>& files() const { return files_; }

  /// The top-level modules the shipped files and `more_sources` import
  /// (numpy, os, rps, ...): a controller module with one of these names
  /// beside the script would be imported in their place.
  std::set<std::string> ImportedModules(const std::vector<std::string>& more_sources) const;

  /// Checks that the controller module at `module_path` can sit beside the
  /// script under its own base name, and returns that name. Refused: a name
  /// that is not an importable module file name (letters, digits, _, not a
  /// keyword, .py), one the submission's own files use (dream, dream_*),
  /// one of `taken` (modules the script and runtime import), and a module
  /// that imports a helper beside it (only the module file is shipped).
  /// @throws std::runtime_error "<config_file>: controller.module: '<path>': <problem>".
  static std::string ControllerFileName(const std::string& module_path, const std::string& module_text,
                                        const std::set<std::string>& taken, const std::string& config_file);

 private:
  std::vector<File> files_;
};

}  // namespace dream::bridge
