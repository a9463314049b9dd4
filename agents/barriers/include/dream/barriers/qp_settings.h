#pragma once

namespace dream::barriers {

/// CVXOPT's stopping options (its defaults here); the barrier certificates of
/// rps set feastol and reltol to 1e-2 and maxiters to 50 and keep abstol's.
struct QpSettings {
  double feasibility_tolerance = 1e-7;
  double absolute_gap_tolerance = 1e-7;
  double relative_gap_tolerance = 1e-6;
  int max_iterations = 100;

  /// What rps sets (rps/utilities/barrier_certificates.py).
  static QpSettings Robotarium() {
    QpSettings settings;
    settings.feasibility_tolerance = 1e-2;
    settings.relative_gap_tolerance = 1e-2;
    settings.max_iterations = 50;
    return settings;
  }
};

}  // namespace dream::barriers
