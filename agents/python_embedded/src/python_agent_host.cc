#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "dream/python_embedded/python_agent_host.h"

#include <pthread.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "dream/config/config_error.h"

namespace dream::python_embedded {
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
  if (type_name == "RunInterrupted") throw std::runtime_error(doing + ": " + message);
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

// The watchdog: one thread per process that stops a controller call running
// too long, or running when the tool is asked to stop (Ctrl-C / SIGTERM set
// its stop flag; Python's own signal handling is off, see EmbeddedModule).
//
// The Python side marks each controller call in `cell` (agent_host.py's
// _answer, embedded.py's check and attach): a token unique to the call, > 0
// for a step, < 0 for loading the module and setup(), 0 between calls; then
// the robot and the step. A few stores per call, nothing else on the hot
// path. The thread polls the cell; when the same step's call has run for
// kStopFraction of the world's agent_timeout_s (loading and setup: of its
// start_timeout_s), or any call runs while `stop` is set, it asks the
// interpreter, with Py_AddPendingCall, to raise ControllerTimeout or
// RunInterrupted in whatever Python code the interpreter's main thread runs
// (taking the GIL once, so that the main thread notices); RaiseInCall checks,
// with the GIL, that the call is still the one it was meant for. The
// exception lands at the next bytecode the call runs, so a call blocked in C
// code that never returns to Python (a long time.sleep, a blocking read) is
// stopped only when it does, or by the process that watches this one through
// the cell (PythonHostProcess). Needs the tools' threading: every call on the
// thread that started the interpreter (its main thread, the only one 3.11
// runs pending calls on). Never freed (the thread outlives every host, and a
// queued pending call may run after one is gone).
class Watchdog {
 public:
  enum Kind : int { kNone = 0, kTimeout = 1, kInterrupt = 2 };
  static constexpr std::chrono::milliseconds kPoll{20};
  static constexpr std::chrono::milliseconds kRepeat{250};  // again, if the call swallowed it

  static Watchdog& Get() {
    static Watchdog* watchdog = new Watchdog();  // never freed: see above
    return *watchdog;
  }

  /// The cell's first word, the call's token (the words after it: robot, step).
  std::atomic<int64_t>* cell() { return cell_.load(); }

  /// A step's call is stopped at this fraction of the world's
  /// agent_timeout_s: early enough that the world hears the fault (and the
  /// other robots' answers) before it gives up on the robots as silent.
  static constexpr double kStopFraction = 0.8;

  void Watch(const std::atomic<bool>* stop, double agent_timeout_s, double start_timeout_s,
             std::atomic<int64_t>* cell) {
    stop_.store(stop);
    agent_timeout_s_.store(agent_timeout_s > 0 ? agent_timeout_s : 0.0);
    start_timeout_s_.store(start_timeout_s > 0 ? start_timeout_s : 0.0);
    if (cell != nullptr) cell_.store(cell);
  }

  /// Starts the thread (once); `timeout_type` and `interrupt_type` are the
  /// Python exception classes it raises (new references, kept). With the GIL.
  void Start(PyObject* timeout_type, PyObject* interrupt_type) {
    if (started_) return;
    timeout_type_ = timeout_type;
    interrupt_type_ = interrupt_type;
    started_ = true;
    std::thread([this] { Loop(); }).detach();
  }

 private:
  static_assert(std::atomic<int64_t>::is_always_lock_free, "the cell is a plain int64 to Python");
  using Clock = std::chrono::steady_clock;

  void Loop() {
    // Ctrl-C and SIGTERM stay the main thread's, as without this thread.
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    int64_t watched = 0;
    Clock::time_point since;
    Clock::time_point last_fired;
    bool fired = false;
    while (true) {
      std::this_thread::sleep_for(kPoll);
      const int64_t token = cell_.load()->load(std::memory_order_relaxed);
      const Clock::time_point now = Clock::now();
      if (token == 0) {
        watched = 0;
        continue;
      }
      if (token != watched) {
        watched = token;
        since = now;
        fired = false;
      }
      const std::atomic<bool>* stop = stop_.load();
      const double limit_s = token > 0 ? agent_timeout_s_.load() : start_timeout_s_.load();
      const double limit = kStopFraction * limit_s;
      Kind kind = kNone;
      if (stop != nullptr && stop->load()) {
        kind = kInterrupt;
      } else if (limit > 0 && std::chrono::duration<double>(now - since).count() > limit) {
        kind = kTimeout;
      }
      if (kind == kNone || (fired && now - last_fired < kRepeat)) continue;
      if (pending_.exchange(true)) continue;  // one queued at a time
      pending_kind_.store(kind);
      pending_token_.store(token);
      pending_limit_s_.store(limit_s);
      if (Py_AddPendingCall(&Watchdog::RaiseInCall, this) != 0) {
        pending_.store(false);  // the queue is full: next poll
        continue;
      }
      // Python 3.11 flags a pending call to the main thread only when that
      // thread recomputes its eval breaker, as it does on taking the GIL
      // back: ask for the GIL once (within the switch interval while the
      // call runs Python code; when the call ended meanwhile, whenever the
      // main thread runs Python again, and RaiseInCall does nothing).
      // Said in the cell (before the GIL, which C code may hold for ever):
      // the process watching this one kills only after it.
      if (kind == kTimeout) cell_.load()[kCallCellRaised].store(token, std::memory_order_relaxed);
      const PyGILState_STATE gil = PyGILState_Ensure();
      PyGILState_Release(gil);
      fired = true;
      last_fired = now;
    }
  }

  // A pending call: the interpreter's main thread, with the GIL, between two
  // bytecodes. -1 with an exception set raises it there.
  static int RaiseInCall(void* self_pointer) {
    Watchdog& self = *static_cast<Watchdog*>(self_pointer);
    const int kind = self.pending_kind_.load();
    const int64_t token = self.pending_token_.load();
    const double limit_s = self.pending_limit_s_.load();
    self.pending_.store(false);
    if (self.cell()->load(std::memory_order_relaxed) != token) return 0;  // that call ended meanwhile
    if (kind == kInterrupt) {
      PyErr_SetString(self.interrupt_type_, "interrupted (Ctrl-C or SIGTERM)");
      return -1;
    }
    char message[160];
    std::snprintf(message, sizeof message, "still running after %g s of the world's %s of %g s: stopped",
                  kStopFraction * limit_s, token > 0 ? "agent_timeout_s" : "start_timeout_s", limit_s);
    PyErr_SetString(self.timeout_type_, message);
    return -1;
  }

  Watchdog() = default;

  std::atomic<int64_t> own_cell_[kCallCellWords] = {};
  std::atomic<std::atomic<int64_t>*> cell_{own_cell_};
  std::atomic<const std::atomic<bool>*> stop_{nullptr};
  std::atomic<double> agent_timeout_s_{0.0};
  std::atomic<double> start_timeout_s_{0.0};
  std::atomic<bool> pending_{false};
  std::atomic<int> pending_kind_{kNone};
  std::atomic<int64_t> pending_token_{0};
  std::atomic<double> pending_limit_s_{0.0};
  bool started_ = false;  // with the GIL
  PyObject* timeout_type_ = nullptr;
  PyObject* interrupt_type_ = nullptr;
};

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
    // the tool's own (StopFlag); the Watchdog brings it into a running
    // controller call as RunInterrupted.
    PyConfig config;
    PyConfig_InitIsolatedConfig(&config);
    config.install_signal_handlers = 0;
    config.site_import = 1;
    // No __pycache__ beside the user's module or in DREAM's install: a run
    // writes only its own folder.
    config.write_bytecode = 0;
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
  Watchdog& watchdog = Watchdog::Get();
  PyRef cell(
      PyMemoryView_FromMemory(reinterpret_cast<char*>(watchdog.cell()), kCallCellWords * sizeof(int64_t), PyBUF_WRITE));
  if (cell.get() == nullptr) ThrowPythonError("cannot set up the Python runtime's watchdog");
  PyRef done(
      PyObject_CallMethod(imported.get(), "setup", "siO", paths.lcmtypes_dir.c_str(), PythonLogLevel(), cell.get()));
  if (done.get() == nullptr) ThrowPythonError("cannot load lcm-gen's Python types from " + paths.lcmtypes_dir);
  PyObject* timeout_type = PyObject_GetAttrString(imported.get(), "ControllerTimeout");
  PyObject* interrupt_type = PyObject_GetAttrString(imported.get(), "RunInterrupted");
  if (timeout_type == nullptr || interrupt_type == nullptr) ThrowPythonError("the Python runtime's watchdog");
  watchdog.Start(timeout_type, interrupt_type);
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
        PyRef text(PyObject_CallMethod(host_, "silence_text", "ds", idle_timeout_s, bus.url().c_str()));
        if (text.get() == nullptr) PyErr_Clear();
        spdlog::error("{}", text.get() != nullptr ? TextOf(text.get()) : "no DREAM_POSES for a while on " + bus.url());
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
}  // namespace dream::python_embedded

// The module's entry points (PythonHostWatchFunction, PythonHostCheckFunction, PythonHostCreateFunction),
// found with dlsym by the tools' PythonHostLibrary.
extern "C" __attribute__((visibility("default"))) void dream_python_host_watch(const std::atomic<bool>* stop,
                                                                               double agent_timeout_s,
                                                                               double start_timeout_s,
                                                                               std::atomic<int64_t>* cell) {
  dream::python_embedded::Watchdog::Get().Watch(stop, agent_timeout_s, start_timeout_s, cell);
}

extern "C" __attribute__((visibility("default"))) void dream_python_host_check(
    const std::string& spec_json, const dream::python_embedded::PythonAgentHost::Paths& paths) {
  using dream::python_embedded::PyRef;
  PyRef result(PyObject_CallMethod(dream::python_embedded::EmbeddedModule(paths), "check", "s", spec_json.c_str()));
  if (result.get() == nullptr) dream::python_embedded::ThrowPythonError("Python controller");
}

extern "C" __attribute__((visibility("default"))) std::unique_ptr<dream::python_embedded::PythonAgentHost>
dream_python_host_create(dream::lcm::LcmBus& bus, const std::string& spec_json, const std::vector<int>& robot_ids,
                         int64_t agent_id, const dream::python_embedded::PythonAgentHost::Paths& paths) {
  return std::make_unique<dream::python_embedded::EmbeddedPythonAgentHost>(bus, spec_json, robot_ids, agent_id, paths);
}
