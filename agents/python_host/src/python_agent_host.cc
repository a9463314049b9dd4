#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "dream/python_host/python_agent_host.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <stdexcept>

#include "dream/config/config_error.h"

namespace dream::agents {
namespace {

/// A strong reference, released when it goes out of scope.
class PyRef {
 public:
  explicit PyRef(PyObject* object = nullptr) : object_(object) {}
  ~PyRef() { Py_XDECREF(object_); }
  PyRef(const PyRef&) = delete;
  PyRef& operator=(const PyRef&) = delete;
  PyObject* get() const { return object_; }
  PyObject* release() {
    PyObject* object = object_;
    object_ = nullptr;
    return object;
  }

 private:
  PyObject* object_;
};

std::string TextOf(PyObject* object) {
  PyRef text(object == nullptr ? nullptr : PyObject_Str(object));
  const char* utf8 = text.get() == nullptr ? nullptr : PyUnicode_AsUTF8(text.get());
  if (utf8 == nullptr) {
    PyErr_Clear();
    return "(no text)";
  }
  return utf8;
}

// The pending Python exception as a C++ one: the runtime's ConfigError (a
// config or controller mistake, already "file:line: key: problem") as
// config::ConfigError, anything else with its type, text and traceback.
[[noreturn]] void ThrowPythonError(const std::string& doing) {
  PyObject* type = nullptr;
  PyObject* value = nullptr;
  PyObject* traceback = nullptr;
  PyErr_Fetch(&type, &value, &traceback);
  PyErr_NormalizeException(&type, &value, &traceback);
  PyRef type_ref(type), value_ref(value), traceback_ref(traceback);
  const std::string type_name =
      type == nullptr ? "error" : TextOf(PyRef(PyObject_GetAttrString(type, "__name__")).get());
  const std::string message = TextOf(value);
  if (type_name == "ConfigError") throw config::ConfigError(message);
  std::string trace;
  if (traceback != nullptr) {
    PyRef module(PyImport_ImportModule("traceback"));
    PyRef lines(module.get() == nullptr
                    ? nullptr
                    : PyObject_CallMethod(module.get(), "format_exception", "OOO", type, value, traceback));
    if (lines.get() != nullptr) {
      PyRef joined(PyUnicode_Join(PyRef(PyUnicode_FromString("")).get(), lines.get()));
      trace = "\n" + TextOf(joined.get());
    }
    PyErr_Clear();
  }
  throw std::runtime_error(doing + ": " + type_name + ": " + message + trace);
}

int PythonLogLevel() {
  switch (spdlog::get_level()) {
    case spdlog::level::trace:
    case spdlog::level::debug:
      return 10;
    case spdlog::level::info:
      return 20;
    case spdlog::level::warn:
      return 30;
    default:
      return 40;
  }
}

// dream.embedded, imported once in an interpreter started once per process.
PyObject* EmbeddedModule(const PythonAgentHost::Paths& paths) {
  static PyObject* module = nullptr;
  if (module != nullptr) return module;
  if (!Py_IsInitialized()) {
    // Isolated: PYTHONPATH, PYTHONHOME and user site-packages of whatever
    // Python the user has on PATH cannot change what the agents run; the
    // system's site-packages (numpy) stay. No signal handlers: Ctrl-C stays
    // the tool's own (StopFlag).
    PyConfig config;
    PyConfig_InitIsolatedConfig(&config);
    config.install_signal_handlers = 0;
    config.site_import = 1;
    const PyStatus status = Py_InitializeFromConfig(&config);
    PyConfig_Clear(&config);
    if (PyStatus_Exception(status)) {
      throw std::runtime_error(std::string("cannot start the embedded Python interpreter: ") +
                               (status.err_msg != nullptr ? status.err_msg : "unknown error"));
    }
  }
  PyObject* sys_path = PySys_GetObject("path");  // borrowed
  PyRef runtime(PyUnicode_FromString(paths.runtime_dir.c_str()));
  if (sys_path == nullptr || runtime.get() == nullptr || PyList_Insert(sys_path, 0, runtime.get()) != 0) {
    ThrowPythonError("cannot set up the Python path");
  }
  PyRef imported(PyImport_ImportModule("dream.embedded"));
  if (imported.get() == nullptr) {
    ThrowPythonError("cannot load the Python runtime from " + paths.runtime_dir);
  }
  PyRef done(PyObject_CallMethod(imported.get(), "setup", "si", paths.lcmtypes_dir.c_str(), PythonLogLevel()));
  if (done.get() == nullptr) ThrowPythonError("cannot load lcm-gen's Python types from " + paths.lcmtypes_dir);
  module = imported.release();
  return module;
}

PyObject* Attribute(PyObject* host, const char* name) {
  PyObject* value = PyObject_GetAttrString(host, name);
  if (value == nullptr) ThrowPythonError(std::string("Python agent host: ") + name);
  return value;
}

/// PythonAgentHost over the embedded interpreter: every call goes to the
/// Python host object (dream.embedded._EmbeddedHost).
class EmbeddedPythonAgentHost final : public PythonAgentHost {
 public:
  EmbeddedPythonAgentHost(lcm::LcmBus& bus, const std::string& spec_json, const std::vector<int>& robot_ids,
                          int64_t agent_id, const Paths& paths) {
    PyObject* module = EmbeddedModule(paths);
    PyRef ids(PyList_New(0));
    for (int id : robot_ids) {
      PyRef item(PyLong_FromLong(id));
      PyList_Append(ids.get(), item.get());
    }
    host_ = PyObject_CallMethod(module, "attach", "KssOL",
                                static_cast<unsigned long long>(reinterpret_cast<uintptr_t>(bus.c_handle())),
                                bus.url().c_str(), spec_json.c_str(), ids.get(), static_cast<long long>(agent_id));
    if (host_ == nullptr) ThrowPythonError("Python controller");
  }

  ~EmbeddedPythonAgentHost() override {
    PyRef closed(PyObject_CallMethod(host_, "close", nullptr));
    if (closed.get() == nullptr) PyErr_Clear();
    Py_DECREF(host_);
  }

  EmbeddedPythonAgentHost(const EmbeddedPythonAgentHost&) = delete;
  EmbeddedPythonAgentHost& operator=(const EmbeddedPythonAgentHost&) = delete;

  bool Run(lcm::LcmBus& bus, const std::atomic<bool>& stop, double idle_timeout_s) override {
    using Clock = std::chrono::steady_clock;
    auto last_activity = Clock::now();
    long seen = -1;
    while (!world_finished() && !stop.load()) {
      bus.HandleSubscriptions(100);
      PyRef poses(Attribute(host_, "poses_seen"));
      const long now_seen = PyLong_AsLong(poses.get());
      if (now_seen != seen) {
        seen = now_seen;
        last_activity = Clock::now();
      } else if (std::chrono::duration<double>(Clock::now() - last_activity).count() > idle_timeout_s) {
        spdlog::error("no DREAM_POSES for {:g} s on {}: is the simulator (dream sim) running on the same LCM URL?",
                      idle_timeout_s, bus.url());
        return false;
      }
    }
    return world_finished();
  }

  bool world_finished() const override {
    PyRef value(Attribute(host_, "world_finished"));
    return PyObject_IsTrue(value.get()) == 1;
  }

  int64_t last_step_answered() const override {
    PyRef value(Attribute(host_, "last_step_answered"));
    return PyLong_AsLongLong(value.get());
  }

  std::string end_detail() const override {
    PyRef value(Attribute(host_, "end_detail"));
    return TextOf(value.get());
  }

  std::string ReportJson() const override {
    PyRef value(PyObject_CallMethod(host_, "report_json", nullptr));
    if (value.get() == nullptr) {
      PyErr_Clear();
      return "{}";
    }
    return TextOf(value.get());
  }

 private:
  PyObject* host_ = nullptr;
};

}  // namespace
}  // namespace dream::agents

// The module's entry points (PythonHostCheckFunction, PythonHostCreateFunction),
// found with dlsym by the tools' PythonHostLibrary.
extern "C" __attribute__((visibility("default"))) void dream_python_host_check(
    const std::string& spec_json, const dream::agents::PythonAgentHost::Paths& paths) {
  using dream::agents::PyRef;
  PyRef result(PyObject_CallMethod(dream::agents::EmbeddedModule(paths), "check", "s", spec_json.c_str()));
  if (result.get() == nullptr) dream::agents::ThrowPythonError("Python controller");
}

extern "C" __attribute__((visibility("default"))) std::unique_ptr<dream::agents::PythonAgentHost>
dream_python_host_create(dream::lcm::LcmBus& bus, const std::string& spec_json, const std::vector<int>& robot_ids,
                         int64_t agent_id, const dream::agents::PythonAgentHost::Paths& paths) {
  return std::make_unique<dream::agents::EmbeddedPythonAgentHost>(bus, spec_json, robot_ids, agent_id, paths);
}
