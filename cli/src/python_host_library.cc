#include "python_host_library.h"

#include <dlfcn.h>

#include <stdexcept>

#include "data_files.h"

namespace dream::cli {

const PythonHostLibrary& PythonHostLibrary::Get() {
  static const PythonHostLibrary library = [] {
    const std::string path = DataFiles::PythonHostModule();
    // RTLD_GLOBAL: libpython's symbols must be visible to the Python
    // extension modules the interpreter loads later (numpy's), which Debian
    // builds without a link to libpython.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (handle == nullptr) {
      const char* error = ::dlerror();
      throw std::runtime_error("cannot load the Python agent host " + path + " (" +
                               (error != nullptr ? error : "unknown error") +
                               "); Python controllers need Debian's libpython3.11 (apt-get install libpython3-dev)");
    }
    auto check = reinterpret_cast<agents::PythonHostCheckFunction>(::dlsym(handle, agents::kPythonHostCheckSymbol));
    auto create =
        reinterpret_cast<agents::PythonHostCreateFunction>(::dlsym(handle, agents::kPythonHostCreateSymbol));
    if (check == nullptr || create == nullptr) {
      throw std::runtime_error(path + " is not the Python agent host of this dream (rebuild or reinstall dream)");
    }
    return PythonHostLibrary(check, create);
  }();
  return library;
}

}  // namespace dream::cli
