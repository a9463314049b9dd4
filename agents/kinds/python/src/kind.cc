#include "dream/python/kind.h"

#include "dream/python/python_controller_builder.h"
#include "dream/python/python_controller_spec.h"

namespace dream::python {

kind_api::ControllerKind Kind() {
  kind_api::ControllerKind kind = kind_api::ControllerKind::Of<PythonControllerBuilder>();
  kind.checks_own_keys = true;  // the Python class declares its own keys (its KEYS)
  kind.runtime = kind_api::ControllerKind::Runtime::kPython;
  kind.runtime_spec = PythonControllerSpecJson;
  kind.file_key = "module";
  return kind;
}

}  // namespace dream::python
