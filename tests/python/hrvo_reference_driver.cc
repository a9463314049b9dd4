// Prints the C++ HrvoExact's or HrvoThesis's answers for the HRVO cases on stdin, one line each, for
// make_hrvo_reference.py (which builds tests/data/hrvo_python_reference.json from them).
// Input line: variant (0 exact, 1 thesis) safety_radius_m max_speed_mps check_boundaries(0/1) boundary_horizon_s
//   keep_right_rad wall_margin_m pos_x pos_y current_x current_y preferred_x preferred_y n
//   then n times: rel_x rel_y vel_x vel_y.
// Output line: vx vy last_was_safe(0/1; always 1 for the thesis), %.17g (round-trips exactly).
#include <cstdio>
#include <iostream>
#include <vector>

#include "dream/agents/hrvo/hrvo_exact.h"
#include "dream/agents/hrvo/hrvo_thesis.h"

int main() {
  using dream::agents::HrvoExact;
  double safety, v_max, horizon, keep_right, margin, px, py, cx, cy, qx, qy;
  int variant, check, n;
  while (std::cin >> variant >> safety >> v_max >> check >> horizon >> keep_right >> margin >> px >> py >> cx >> cy >>
         qx >> qy >> n) {
    std::vector<dream::agents::HrvoNeighbour> neighbours(static_cast<size_t>(n));
    for (auto& h : neighbours) {
      std::cin >> h.relative_position_m.x() >> h.relative_position_m.y() >> h.velocity_mps.x() >> h.velocity_mps.y();
    }
    dream::agents::HrvoParams params;
    params.safety_radius_m = safety;
    params.max_speed_mps = v_max;
    params.check_boundaries = check != 0;
    params.boundary_horizon_s = horizon;
    HrvoExact exact(params, {keep_right, margin});
    dream::agents::HrvoThesis thesis(params);
    dream::agents::HrvoAvoidance& hrvo = variant == 1 ? static_cast<dream::agents::HrvoAvoidance&>(thesis) : exact;
    const Eigen::Vector2d v = hrvo.SafeVelocity({px, py}, {cx, cy}, {qx, qy}, neighbours);
    std::printf("%.17g %.17g %d\n", v.x(), v.y(), variant == 1 || exact.last_was_safe() ? 1 : 0);
  }
  return 0;
}
