#pragma once

#include "dream/barriers/single_integrator_barrier_params.h"
#include "dream/config/config_node.h"
#include "dream/barriers/unicycle_barrier_params.h"

namespace dream::run_config {

/// A run config's `barriers:` section (config/README.md#barriers): which of
/// the Robotarium's barrier certificates the run uses, with what parameters,
/// and who applies it.
struct BarrierConfig {
  enum class Kind {
    kNone,              ///< no certificate (the default)
    kUnicycle,          ///< rps's create_uni_barrier_certificate[_with_boundary]
    kSingleIntegrator,  ///< rps's create_si_barrier_certificate[_with_boundary] (controller only)
  };
  enum class ApplyIn {
    kWorld,       ///< the simulator filters every step's commands, and the export's script does too
    kController,  ///< the controller calls it itself (dream.barriers), so it ships with the controller
  };

  Kind kind = Kind::kNone;
  ApplyIn apply_in = ApplyIn::kWorld;
  /// Kind unicycle: rps's create_uni_barrier_certificate_with_boundary() unless the keys say otherwise.
  barriers::UnicycleBarrierParams unicycle = barriers::UnicycleBarrierParams::RpsWithBoundary();
  /// Kind single_integrator: rps's create_si_barrier_certificate_with_boundary() unless the keys say otherwise.
  barriers::SingleIntegratorBarrierParams single_integrator =
      barriers::SingleIntegratorBarrierParams::RpsWithBoundary();

  /// The simulator (and the exported script) filter commands through `unicycle`.
  bool InWorld() const { return kind == Kind::kUnicycle && apply_in == ApplyIn::kWorld; }
  /// The config's `barriers:` section (none: kind none). Each key's default is
  /// rps's for the kind; a key the kind does not take is a mistake naming file, line and key.
  /// @throws config::ConfigError.
  static BarrierConfig Read(const config::ConfigNode& root);
  static const char* KindName(Kind kind);
  static const char* ApplyInName(ApplyIn apply_in);
};

}  // namespace dream::run_config
