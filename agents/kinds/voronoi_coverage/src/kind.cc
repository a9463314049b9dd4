#include "dream/voronoi_coverage/kind.h"

#include "dream/voronoi_coverage/voronoi_coverage_builder.h"

namespace dream::voronoi_coverage {

kind_api::ControllerKind Kind() { return kind_api::ControllerKind::Of<VoronoiCoverageBuilder>(); }

}  // namespace dream::voronoi_coverage
