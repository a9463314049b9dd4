#include "dream/calibration_drive/kind.h"

#include "dream/calibration_drive/calibration_drive_builder.h"

namespace dream::calibration_drive {

kind_api::ControllerKind Kind() { return kind_api::ControllerKind::Of<CalibrationDriveBuilder>(); }

}  // namespace dream::calibration_drive
