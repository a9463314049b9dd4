#include "dream/affine_formation/kind.h"

#include "dream/affine_formation/affine_formation_builder.h"

namespace dream::affine_formation {

kind_api::ControllerKind Kind() { return kind_api::ControllerKind::Of<AffineFormationBuilder>(); }

}  // namespace dream::affine_formation
