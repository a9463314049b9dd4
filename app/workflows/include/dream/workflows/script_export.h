#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace dream::workflows {

/// `dream export SCRIPT.py` (docs/robotarium-scripts.md#the-upload): the
/// upload of a Robotarium script is the script itself, byte for byte, and
/// DREAM's recorder as its main file (kRecorderName: it runs the script as
/// __main__ and saves the poses it read and the commands it sent as
/// dream_result.npy, which `dream import` reads). This copies both into
/// <out>/upload/ once a checker (python/rps_dream/check_imports.py, started by
/// the caller) found that the script imports only what the Robotarium has,
/// and writes a manifest (script_export.json) that `dream check-submission`
/// and `dream import` read.
class ScriptExport {
 public:
  struct Options {
    std::string script_path;
    std::string out_dir;             ///< empty: exports/<the script's run name>
    std::string libraries_path;      ///< the official simulator's libraries.txt; empty: its requirements
    std::string python;              ///< runs the checker
    std::string python_runtime_dir;  ///< its rps_dream/check_imports.py
  };
  /// What the checker printed (stdout and stderr) and its exit code.
  struct Checked {
    int exit_code = 0;
    std::string output;
  };
  using RunChecker = std::function<Checked(const std::vector<std::string>& argv)>;

  struct Result {
    bool refused = false;
    std::string refusal;  ///< what the Robotarium lacks, when refused: nothing written
    std::string out_dir;
    std::string main_file;    ///< the upload's file to name as the main file: the recorder
    std::string script_file;  ///< the script's file in the upload
    std::vector<std::string> imports;
  };

  /// The manifest of a script's export, in its folder.
  struct Manifest {
    std::string script;     ///< the source, as exported
    std::string main_file;  ///< upload/<main_file>
    std::string sha256;     ///< of upload/<main_file> when exported
    /// The script's file in upload/ and its SHA-256 (empty in an export
    /// made before the recorder: the script was the main file).
    std::string script_file;
    std::string script_sha256;
  };
  static constexpr const char* kManifestName = "script_export.json";
  /// The recorder's name in the upload (python/rps_dream/dream_record.py).
  static constexpr const char* kRecorderName = "dream_record.py";

  /// @throws std::runtime_error naming the script when it is missing or the
  ///         checker cannot read it (a syntax error, with its line).
  Result Export(const Options& options, const RunChecker& run_checker) const;

  /// The manifest of `export_dir`, or nothing when it holds no script's export.
  /// @throws std::runtime_error naming the file when it is damaged.
  static std::optional<Manifest> Read(const std::string& export_dir);
};

}  // namespace dream::workflows
